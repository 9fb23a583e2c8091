// CGAL 5.5's side of the demo-mesh comparison (benches/demo_meshes.sh, with
// `cargo bench --bench demo_meshes` on the same files in the same run). EPICK kernel,
// Surface_mesh, one thread (CGAL's default sequential tag).
//
// Usage:
//   cgal_demo_meshes self LIST_FILE REPEAT OUT_DIR
//     For each mesh path in LIST_FILE (one a line): read it with CGAL::IO::read_polygon_mesh,
//     triangulate it with PMP::triangulate_faces when it is not a triangle mesh (then
//     "triangulated": true), and time PMP::self_intersections (best and mean of REPEAT runs,
//     reading excluded). Writes the pairs (face indices i < j, sorted, `i j` a line) to
//     OUT_DIR/<file name>.pairs and prints one JSON line per mesh. CGAL reports a degenerate
//     face f as the pair (f, f) and tests it against nothing else: those are counted under
//     "degenerate" and left out of the pair list. "file_order" says whether face k of the mesh
//     has the corners of polygon k of the file (checked on the soup read with
//     CGAL::IO::read_polygon_soup; null when triangulated), i.e. whether the indices are
//     comparable with another reader's. A mesh CGAL cannot read gives {"mesh":..., "error":...}.
//   cgal_demo_meshes pair MESH_A MESH_B REPEAT OUT_FILE
//     Every pair (face i of A, face j of B) of intersecting closed triangles: the faces'
//     Bbox_3 boxes through CGAL::box_intersection_d (closed boxes), then the exact
//     CGAL::do_intersect(Triangle_3, Triangle_3) on each box pair. A degenerate face (collinear
//     corners, outside do_intersect's precondition) is tested as its segment or point instead.
//     Timed best and mean of REPEAT runs, building the boxes included. Writes the sorted pairs
//     to OUT_FILE and prints one JSON line.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Segment = Kernel::Segment_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Face = boost::graph_traits<Mesh>::face_descriptor;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
namespace PMP = CGAL::Polygon_mesh_processing;
using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

static std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

static std::string json_number(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

static std::string file_name(const std::string& path) {
  auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

static void write_pairs(const std::string& path, const Pairs& pairs) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  for (const auto& p : pairs) out << p.first << ' ' << p.second << '\n';
  if (!out) throw std::runtime_error("error writing " + path);
}

// Best and mean of `repeat` runs of f, in milliseconds (steady clock); runs go on past `repeat`
// until they add up to 20 ms (at most 100,000), so that the best time of a mesh taking a few
// microseconds is not the luck of a few cold runs (the Rust driver uses the same rule).
template <class F> static std::pair<double, double> timed(int repeat, F f) {
  double best = 1e300, sum = 0.0;
  int runs = 0;
  while (runs < repeat || (sum < 20.0 && runs < 100000)) {
    auto t0 = std::chrono::steady_clock::now();
    f();
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    best = std::min(best, ms);
    sum += ms;
    ++runs;
  }
  return {best, sum / runs};
}

static std::array<Point, 3> corners(const Mesh& m, Face f) {
  auto h = halfedge(f, m);
  return {m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m))};
}

// Reads a mesh; triangulates it when needed (sets `triangulated`). Throws on failure.
static Mesh read_mesh(const std::string& path, bool& triangulated) {
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(path, mesh)) {
    // Not a 2-manifold polygon mesh as written (e.g. the *-shuffled meshes, whose faces are
    // inconsistently oriented): read the soup, orient it, and build the mesh from it (faces
    // keep the file's order; points on non-manifold vertices may be duplicated).
    std::vector<Point> points;
    std::vector<std::vector<std::size_t>> polygons;
    if (!CGAL::IO::read_polygon_soup(path, points, polygons) || polygons.empty())
      throw std::runtime_error("CGAL::IO::read_polygon_mesh and read_polygon_soup failed");
    PMP::orient_polygon_soup(points, polygons);
    PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  }
  triangulated = false;
  if (!CGAL::is_triangle_mesh(mesh)) {
    if (!PMP::triangulate_faces(mesh)) throw std::runtime_error("PMP::triangulate_faces failed");
    triangulated = true;
  }
  return mesh;
}

// Whether face k of the mesh has the corners of polygon k of the file's polygon soup.
static bool same_order_as_file(const std::string& path, const Mesh& mesh) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(path, points, polygons)) return false;
  if (polygons.size() != num_faces(mesh)) return false;
  std::size_t k = 0;
  for (Face f : faces(mesh)) {
    if (static_cast<std::size_t>(f) != k) return false;
    const auto& poly = polygons[k++];
    if (poly.size() != 3) return false;
    auto c = corners(mesh, f);
    std::array<Point, 3> s{points[poly[0]], points[poly[1]], points[poly[2]]};
    std::sort(c.begin(), c.end());
    std::sort(s.begin(), s.end());
    if (c != s) return false;
  }
  return true;
}

static void self_mode(const std::string& list, int repeat, const std::string& out_dir) {
  std::ifstream in(list);
  if (!in) throw std::runtime_error("cannot read " + list);
  std::string path;
  while (std::getline(in, path)) {
    if (path.empty()) continue;
    const std::string name = file_name(path);
    try {
      bool triangulated = false;
      Mesh mesh = read_mesh(path, triangulated);
      std::vector<std::pair<Face, Face>> raw;
      auto [best, mean] = timed(repeat, [&] {
        raw.clear();
        PMP::self_intersections(mesh, std::back_inserter(raw));
      });
      Pairs pairs;
      std::size_t degenerate = 0;
      for (const auto& [f, g] : raw) {
        std::size_t i = static_cast<std::size_t>(f), j = static_cast<std::size_t>(g);
        if (i == j)
          ++degenerate;
        else
          pairs.emplace_back(std::min(i, j), std::max(i, j));
      }
      std::sort(pairs.begin(), pairs.end());
      write_pairs(out_dir + "/" + name + ".pairs", pairs);
      std::string order = triangulated ? "null" : (same_order_as_file(path, mesh) ? "true" : "false");
      std::cout << "{\"mesh\":" << json_string(name) << ",\"triangles\":" << num_faces(mesh)
                << ",\"triangulated\":" << (triangulated ? "true" : "false") << ",\"pairs\":" << pairs.size()
                << ",\"degenerate\":" << degenerate << ",\"best_ms\":" << json_number(best)
                << ",\"mean_ms\":" << json_number(mean) << ",\"file_order\":" << order << "}" << std::endl;
    } catch (const std::exception& e) {
      std::cout << "{\"mesh\":" << json_string(name) << ",\"error\":" << json_string(e.what()) << "}" << std::endl;
    }
  }
}

// A face as what it is: a triangle, or (collinear corners) the segment spanning them, or a point.
struct Piece {
  int kind;  // 2: triangle, 1: segment, 0: point
  Triangle t;
  Segment s;
  Point p;
};

static Piece piece(const std::array<Point, 3>& c) {
  Piece x;
  if (!CGAL::collinear(c[0], c[1], c[2])) {
    x.kind = 2;
    x.t = Triangle(c[0], c[1], c[2]);
    return x;
  }
  auto lo = std::min({c[0], c[1], c[2]}), hi = std::max({c[0], c[1], c[2]});  // lexicographic ends
  if (lo == hi) {
    x.kind = 0;
    x.p = lo;
  } else {
    x.kind = 1;
    x.s = Segment(lo, hi);
  }
  return x;
}

static bool meet(const Piece& a, const Piece& b) {
  if (a.kind < b.kind) return meet(b, a);
  switch (a.kind * 3 + b.kind) {
    case 8: return CGAL::do_intersect(a.t, b.t);
    case 7: return CGAL::do_intersect(a.t, b.s);
    case 6: return a.t.has_on(b.p);
    case 4: return CGAL::do_intersect(a.s, b.s);
    case 3: return a.s.has_on(b.p);
    default: return a.p == b.p;
  }
}

static void pair_mode(const std::string& pa, const std::string& pb, int repeat, const std::string& out_file) {
  const std::string na = file_name(pa), nb = file_name(pb);
  bool ta = false, tb = false;
  Mesh a, b;
  try {
    a = read_mesh(pa, ta);
    b = read_mesh(pb, tb);
  } catch (const std::exception& e) {
    std::cout << "{\"a\":" << json_string(na) << ",\"b\":" << json_string(nb) << ",\"error\":" << json_string(e.what())
              << "}" << std::endl;
    return;
  }
  Pairs pairs;
  auto [best, mean] = timed(repeat, [&] {
    pairs.clear();
    std::vector<Piece> pieces_a, pieces_b;
    std::vector<Box> boxes_a, boxes_b;
    auto build = [](const Mesh& m, std::vector<Piece>& pieces, std::vector<Box>& boxes) {
      pieces.reserve(num_faces(m));
      boxes.reserve(num_faces(m));
      for (Face f : faces(m)) {
        auto c = corners(m, f);
        pieces.push_back(piece(c));
        boxes.emplace_back(c[0].bbox() + c[1].bbox() + c[2].bbox(), static_cast<std::size_t>(f));
      }
    };
    build(a, pieces_a, boxes_a);
    build(b, pieces_b, boxes_b);
    CGAL::box_intersection_d(boxes_a.begin(), boxes_a.end(), boxes_b.begin(), boxes_b.end(),
                             [&](const Box& x, const Box& y) {
                               if (meet(pieces_a[x.info()], pieces_b[y.info()])) pairs.emplace_back(x.info(), y.info());
                             });
  });
  std::sort(pairs.begin(), pairs.end());
  write_pairs(out_file, pairs);
  std::cout << "{\"a\":" << json_string(na) << ",\"b\":" << json_string(nb) << ",\"triangles_a\":" << num_faces(a)
            << ",\"triangles_b\":" << num_faces(b) << ",\"triangulated\":" << ((ta || tb) ? "true" : "false")
            << ",\"pairs\":" << pairs.size() << ",\"best_ms\":" << json_number(best)
            << ",\"mean_ms\":" << json_number(mean) << "}" << std::endl;
}

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.size() == 4 && args[0] == "self") {
      self_mode(args[1], std::max(1, std::atoi(args[2].c_str())), args[3]);
      return 0;
    }
    if (args.size() == 5 && args[0] == "pair") {
      pair_mode(args[1], args[2], std::max(1, std::atoi(args[3].c_str())), args[4]);
      return 0;
    }
  } catch (const std::exception& e) {
    std::cerr << argv[0] << ": " << e.what() << "\n";
    return 1;
  }
  std::cerr << "usage: " << argv[0] << " self LIST_FILE REPEAT OUT_DIR\n"
            << "       " << argv[0] << " pair MESH_A MESH_B REPEAT OUT_FILE\n";
  return 2;
}
