// FCL's collide() on primitive pairs, for comparison with `cga shapes` on the same pair files.
// Build and run with `bash cga-collide/benches/fcl_shapes.sh` (needs Debian's libfcl-dev,
// FCL 0.7); the input is written by peer_shapes.py --fcl-text from shape_pairs.py's JSONL.
//
// Input, three lines per pair:
//   PAIR <pair type> <family> <expected: 1, 0, or -1 for unknown> <exact input: 1 or 0>
//   <shape a>
//   <shape b>
// A shape line is KIND PARAMS... followed by its pose, R (9 numbers, row-major) and t (3):
//   sphere r | box x y z (full side lengths) | capsule r lz | cylinder r lz | cone r lz
//   (apex at +lz/2) | halfspace nx ny nz d ({x : n.x <= d}, n of unit length) |
//   triangle x0 y0 z0 x1 y1 z1 x2 y2 z2 (made a one-triangle BVHModel<OBBRSS>: FCL 0.7 has no
//   shape pairs with TriangleP) | convex NV NF x y z ... (NV points) i j k ... (NF
//   outward triangles) | unsupported (a shape the conversion could not make; an error).
// Numbers are written with Python's repr and read with strtod, so they are the same f64.
//
// Each pair: fcl::collide(geom_a, tf_a, geom_b, tf_b, request, result) with the default
// CollisionRequest (libccd GJK, one contact), result.clear() before every call; 5 loops of
// REPEAT / 5 calls, the best loop's time per call. The answer is collide() > 0. A pair FCL
// reports as unsupported (a warning on stderr) or that throws is an error, not an answer.
// micros_call_cost: the same loops on two unit spheres 10 apart (dispatch and result
// handling, the floor of any call), timed right before each pair, median; micros_net: the
// median over the pairs of (pair time - the call cost timed next to it).
//
// Usage: fcl_shapes INPUT [--repeat N] [--wrong FILE]
// Prints one JSON line per (pair type, family), the fields of coal_shapes.py with "who": "fcl".
// --wrong FILE writes "<line number of the PAIR line> <pair> <family> expected answer exact" for
// every wrong answer.
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/cone.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/halfspace.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using S = double;
using Geometry = std::shared_ptr<fcl::CollisionGeometry<S>>;

[[noreturn]] static void fail(const std::string& msg) { throw std::runtime_error(msg); }

struct Shape {
  Geometry geometry;  // null: unsupported by the conversion
  fcl::Transform3<S> pose = fcl::Transform3<S>::Identity();
};

struct Pair {
  long line = 0;
  std::string type, family;
  int expected = -1;
  bool exact = false;
  Shape a, b;
};

static S number(std::istringstream& in, long line) {
  std::string word;
  if (!(in >> word)) fail("line " + std::to_string(line) + ": a number is missing");
  char* end = nullptr;
  S x = std::strtod(word.c_str(), &end);
  if (end == word.c_str() || *end != '\0') fail("line " + std::to_string(line) + ": bad number " + word);
  return x;
}

static long integer(std::istringstream& in, long line) {
  long i;
  if (!(in >> i)) fail("line " + std::to_string(line) + ": an integer is missing");
  return i;
}

static Shape read_shape(const std::string& text, long line) {
  std::istringstream in(text);
  std::string kind;
  in >> kind;
  Shape s;
  auto num = [&] { return number(in, line); };
  if (kind == "unsupported") return s;
  if (kind == "sphere") {
    s.geometry = std::make_shared<fcl::Sphere<S>>(num());
  } else if (kind == "box") {
    S x = num(), y = num(), z = num();
    s.geometry = std::make_shared<fcl::Box<S>>(x, y, z);
  } else if (kind == "capsule" || kind == "cylinder" || kind == "cone") {
    S r = num(), lz = num();
    if (kind == "capsule") s.geometry = std::make_shared<fcl::Capsule<S>>(r, lz);
    if (kind == "cylinder") s.geometry = std::make_shared<fcl::Cylinder<S>>(r, lz);
    if (kind == "cone") s.geometry = std::make_shared<fcl::Cone<S>>(r, lz);
  } else if (kind == "halfspace") {
    S nx = num(), ny = num(), nz = num(), d = num();
    s.geometry = std::make_shared<fcl::Halfspace<S>>(fcl::Vector3<S>(nx, ny, nz), d);
  } else if (kind == "triangle") {
    fcl::Vector3<S> p[3];
    for (auto& v : p) {
      S x = num(), y = num(), z = num();
      v = fcl::Vector3<S>(x, y, z);
    }
    // FCL 0.7's collision table has no TriangleP pairs: a triangle is a one-triangle mesh.
    auto mesh = std::make_shared<fcl::BVHModel<fcl::OBBRSS<S>>>();
    mesh->beginModel(1, 3);
    mesh->addTriangle(p[0], p[1], p[2]);
    mesh->endModel();
    s.geometry = mesh;
  } else if (kind == "convex") {
    long nv = integer(in, line), nf = integer(in, line);
    if (nv < 4 || nf < 4) fail("line " + std::to_string(line) + ": convex with too few vertices or faces");
    auto verts = std::make_shared<std::vector<fcl::Vector3<S>>>();
    for (long i = 0; i < nv; ++i) {
      S x = num(), y = num(), z = num();
      verts->emplace_back(x, y, z);
    }
    auto faces = std::make_shared<std::vector<int>>();
    for (long f = 0; f < nf; ++f) {
      faces->push_back(3);
      for (int k = 0; k < 3; ++k) {
        long i = integer(in, line);
        if (i < 0 || i >= nv) fail("line " + std::to_string(line) + ": face index out of range");
        faces->push_back(static_cast<int>(i));
      }
    }
    s.geometry = std::make_shared<fcl::Convex<S>>(verts, static_cast<int>(nf), faces);
  } else {
    fail("line " + std::to_string(line) + ": unknown shape " + kind);
  }
  fcl::Matrix3<S> rot;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) rot(i, j) = num();
  S tx = num(), ty = num(), tz = num();
  s.pose.linear() = rot;
  s.pose.translation() = fcl::Vector3<S>(tx, ty, tz);
  s.geometry->computeLocalAABB();
  return s;
}

static std::vector<Pair> read_pairs(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail("cannot open " + path);
  std::vector<Pair> pairs;
  std::string text;
  long line = 0;
  while (std::getline(in, text)) {
    ++line;
    if (text.empty()) continue;
    std::istringstream head(text);
    std::string tag;
    Pair p;
    int exact = 0;
    if (!(head >> tag >> p.type >> p.family >> p.expected >> exact) || tag != "PAIR")
      fail(path + ":" + std::to_string(line) + ": expected a PAIR line");
    p.line = line;
    p.exact = exact != 0;
    std::string sa, sb;
    if (!std::getline(in, sa) || !std::getline(in, sb)) fail(path + ": a pair lacks its shapes");
    p.a = read_shape(sa, line + 1);
    p.b = read_shape(sb, line + 2);
    line += 2;
    pairs.push_back(std::move(p));
  }
  return pairs;
}

struct Timed {
  bool answer = false;
  bool error = false;
  double micros = 0;
};

static volatile std::size_t sink_ = 0;  // the timed calls' results, kept so none is elided

// The first call gives the answer (and tells whether FCL complains on stderr); then the
// best of `batches` timed loops.
static Timed time_pair(const Shape& a, const Shape& b, long repeat, int batches = 5) {
  Timed t;
  if (!a.geometry || !b.geometry) {
    t.error = true;
    return t;
  }
  fcl::CollisionRequest<S> request;
  fcl::CollisionResult<S> result;
  std::ostringstream captured;
  std::streambuf* saved = std::cerr.rdbuf(captured.rdbuf());
  try {
    t.answer = fcl::collide(a.geometry.get(), a.pose, b.geometry.get(), b.pose, request, result) > 0;
  } catch (const std::exception& e) {
    captured << e.what();
  }
  std::cerr.rdbuf(saved);
  if (!captured.str().empty()) {
    std::cerr << "fcl: " << captured.str() << (captured.str().back() == '\n' ? "" : "\n");
    t.error = true;
    return t;
  }
  long n = std::max(1L, repeat / batches);
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < batches; ++k) {
    auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < n; ++i) {
      result.clear();
      sink_ += fcl::collide(a.geometry.get(), a.pose, b.geometry.get(), b.pose, request, result);
    }
    auto stop = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::micro>(stop - start).count() / n);
  }
  t.micros = best;
  return t;
}

static double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

static std::string json_number(double x) {
  if (x != x) return "null";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", x);
  return buf;
}

int main(int argc, char** argv) {
  try {
    if (argc < 2) fail("usage: fcl_shapes INPUT [--repeat N] [--wrong FILE]");
    std::string input = argv[1], wrong_path;
    long repeat = 200;
    for (int i = 2; i < argc; ++i) {
      std::string arg = argv[i];
      if (arg == "--repeat" && i + 1 < argc) repeat = std::atol(argv[++i]);
      else if (arg == "--wrong" && i + 1 < argc) wrong_path = argv[++i];
      else fail("unknown argument " + arg);
    }
    std::vector<Pair> pairs = read_pairs(input);
    Shape far_a, far_b;
    far_a.geometry = std::make_shared<fcl::Sphere<S>>(1.0);
    far_b.geometry = std::make_shared<fcl::Sphere<S>>(1.0);
    far_a.geometry->computeLocalAABB();
    far_b.geometry->computeLocalAABB();
    far_b.pose.translation() = fcl::Vector3<S>(10, 0, 0);

    struct Group {
      std::vector<double> micros, call_costs, net;
      long pairs = 0, false_collisions = 0, missed = 0, exact = 0, wrong_exact = 0, errors = 0;
    };
    std::map<std::pair<std::string, std::string>, Group> groups;
    std::ofstream wrong;
    if (!wrong_path.empty()) wrong.open(wrong_path);
    for (size_t i = 0; i < pairs.size(); ++i) {
      const Pair& p = pairs[i];
      Group& g = groups[{p.type, p.family}];
      ++g.pairs;
      g.exact += p.exact;
      double call = time_pair(far_a, far_b, repeat).micros;
      Timed t = time_pair(p.a, p.b, repeat);
      if (t.error) {
        ++g.errors;
        continue;
      }
      g.micros.push_back(t.micros);
      g.call_costs.push_back(call);
      g.net.push_back(t.micros - call);
      if (p.expected < 0 || t.answer == (p.expected == 1)) continue;
      if (t.answer) ++g.false_collisions;
      else ++g.missed;
      if (p.exact) ++g.wrong_exact;
      if (wrong) wrong << p.line << " " << p.type << " " << p.family << " " << p.expected << " " << t.answer
                       << " " << p.exact << "\n";
    }
    for (const auto& [key, g] : groups) {
      double med = median(g.micros);
      std::cout << "{\"who\": \"fcl\", \"pair\": \"" << key.first << "\", \"family\": \"" << key.second
                << "\", \"pairs\": " << g.pairs << ", \"micros_median\": " << json_number(med)
                << ", \"micros_call_cost\": " << json_number(median(g.call_costs))
                << ", \"micros_net\": " << json_number(median(g.net))
                << ", \"wrong\": " << g.false_collisions + g.missed
                << ", \"false_collisions\": " << g.false_collisions << ", \"missed\": " << g.missed
                << ", \"exact_input_pairs\": " << g.exact << ", \"wrong_exact_input\": " << g.wrong_exact
                << ", \"errors\": " << g.errors << "}\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "fcl_shapes: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
