// FCL's dynamic AABB tree broad phase on scenes of many mesh objects, for comparison with
// our scene on the same scene files. Build and run with `bash cga-collide/benches/fcl_scene.sh`
// (needs Debian's libfcl-dev); scene files come from make_scene.py, whose header describes
// the format.
//
// Usage: fcl_scene SCENE [--moved MOVED] [--repeat R] [--pairs]
//
// One BVHModel<OBBRSS> per distinct mesh, shared by its objects; one CollisionObject per
// object, all in a DynamicAABBTreeCollisionManager. millis_load (once): reading the meshes,
// building their BVHs and creating the objects. Timed R times each (best and mean, ms):
//   build            registerObjects + setup on a fresh manager
//   pairs            collide() with a callback that runs the narrow phase on every culled
//                    pair (num_max_contacts = 1) and records each colliding one, never stopping
//   move_and_pairs   setTransform + computeAABB for every object to the moved poses,
//                    update(), then pairs again (the poses are put back, untimed, in between)
//   nearest          distance() with the minimum-distance callback (prunes with the best
//                    distance so far, stops at distance <= 0 like FCL's default callback)
// Prints one JSON object on stdout; --pairs adds the colliding pairs (i < j, sorted).
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <chrono>
#include <cmath>
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
using Model = fcl::BVHModel<fcl::OBBRSS<S>>;
using Object = fcl::CollisionObject<S>;

[[noreturn]] static void fail(const std::string& msg) { throw std::runtime_error(msg); }

// ---- meshes ------------------------------------------------------------------------------

struct Mesh {
  std::vector<fcl::Vector3<S>> vertices;
  std::vector<fcl::Triangle> triangles;
};

static void fan(Mesh& m, const std::vector<long>& poly, const std::string& path) {
  if (poly.size() < 3) fail(path + ": face with fewer than 3 vertices");
  for (long i : poly)
    if (i < 0 || i >= static_cast<long>(m.vertices.size())) fail(path + ": vertex index out of range");
  for (size_t k = 1; k + 1 < poly.size(); ++k) m.triangles.emplace_back(poly[0], poly[k], poly[k + 1]);
}

static Mesh read_obj(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail("cannot open " + path);
  Mesh m;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    if (!(ls >> tag)) continue;
    if (tag == "v") {
      S x, y, z;
      if (!(ls >> x >> y >> z)) fail(path + ": bad vertex line: " + line);
      m.vertices.emplace_back(x, y, z);
    } else if (tag == "f") {
      std::vector<long> poly;
      std::string word;
      while (ls >> word) {
        long i = std::stol(word.substr(0, word.find('/')));  // "a", "a/b", "a//c", "a/b/c"
        poly.push_back(i > 0 ? i - 1 : static_cast<long>(m.vertices.size()) + i);  // negative: relative
      }
      fan(m, poly, path);
    }
  }
  return m;
}

// OFF, line by line: "OFF" (counts may follow on the same line), "nv nf ne", nv lines
// "x y z ...", nf lines "k i0 .. ik-1 ..." (anything after the indices, e.g. colours, ignored).
static Mesh read_off(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail("cannot open " + path);
  std::vector<std::string> lines;  // non-empty lines, comments stripped
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
  }
  std::istringstream head(lines.empty() ? "" : lines[0]);
  std::string magic;
  head >> magic;
  if (magic.size() < 3 || magic.compare(magic.size() - 3, 3, "OFF") != 0) fail(path + ": not an OFF file");
  size_t at = 1;
  long nv, nf;
  if (!(head >> nv >> nf)) {
    if (at >= lines.size()) fail(path + ": no counts");
    std::istringstream counts(lines[at++]);
    if (!(counts >> nv >> nf)) fail(path + ": bad counts");
  }
  if (lines.size() < at + nv + nf) fail(path + ": truncated");
  Mesh m;
  for (long i = 0; i < nv; ++i) {
    std::istringstream ls(lines[at++]);
    S x, y, z;
    if (!(ls >> x >> y >> z)) fail(path + ": bad vertex line: " + lines[at - 1]);
    m.vertices.emplace_back(x, y, z);
  }
  for (long f = 0; f < nf; ++f) {
    std::istringstream ls(lines[at++]);
    long k, i;
    std::vector<long> poly;
    if (!(ls >> k)) fail(path + ": bad face line");
    for (long j = 0; j < k && ls >> i; ++j) poly.push_back(i);
    if (static_cast<long>(poly.size()) != k) fail(path + ": bad face line: " + lines[at - 1]);
    fan(m, poly, path);
  }
  return m;
}

static std::shared_ptr<Model> load_model(const std::string& path) {
  std::string lower = path;
  std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
  Mesh m = lower.size() >= 4 && lower.compare(lower.size() - 4, 4, ".off") == 0 ? read_off(path) : read_obj(path);
  auto model = std::make_shared<Model>();
  model->beginModel(static_cast<int>(m.triangles.size()), static_cast<int>(m.vertices.size()));
  model->addSubModel(m.vertices, m.triangles);
  model->endModel();
  model->computeLocalAABB();
  return model;
}

// ---- scene files -------------------------------------------------------------------------

struct Entry {
  std::string mesh;  // path as resolved against the scene file's folder
  fcl::Transform3<S> pose;
};

static fcl::Transform3<S> pose_from(const std::vector<S>& n, const std::string& where) {
  fcl::Transform3<S> tf = fcl::Transform3<S>::Identity();
  if (n.size() == 6) {
    const S deg = M_PI / 180.0;
    fcl::Matrix3<S> r = (fcl::AngleAxis<S>(n[2] * deg, fcl::Vector3<S>::UnitZ()) *
                         fcl::AngleAxis<S>(n[1] * deg, fcl::Vector3<S>::UnitY()) *
                         fcl::AngleAxis<S>(n[0] * deg, fcl::Vector3<S>::UnitX()))
                            .toRotationMatrix();
    tf.linear() = r;
    tf.translation() = fcl::Vector3<S>(n[3], n[4], n[5]);
  } else if (n.size() == 12) {
    fcl::Matrix3<S> r;
    r << n[0], n[1], n[2], n[4], n[5], n[6], n[8], n[9], n[10];
    tf.linear() = r;
    tf.translation() = fcl::Vector3<S>(n[3], n[7], n[11]);
  } else {
    fail(where + ": expected a mesh path and 6 or 12 numbers");
  }
  return tf;
}

static std::vector<Entry> read_scene(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail("cannot open " + path);
  std::string dir = path.find('/') == std::string::npos ? "" : path.substr(0, path.rfind('/') + 1);
  std::vector<Entry> out;
  std::string line;
  for (int lineno = 1; std::getline(in, line); ++lineno) {
    std::istringstream ls(line.substr(0, line.find('#')));
    std::string mesh;
    if (!(ls >> mesh)) continue;
    std::vector<S> nums;
    std::string w;
    while (ls >> w) {
      size_t used = 0;
      S x = std::stod(w, &used);
      if (used != w.size()) fail(path + ":" + std::to_string(lineno) + ": not a number: " + w);
      nums.push_back(x);
    }
    out.push_back({mesh[0] == '/' ? mesh : dir + mesh, pose_from(nums, path + ":" + std::to_string(lineno))});
  }
  return out;
}

// ---- callbacks ---------------------------------------------------------------------------

static long index_of(Object* o) { return static_cast<long>(reinterpret_cast<intptr_t>(o->getUserData())); }

struct PairsData {
  fcl::CollisionRequest<S> request{1};  // num_max_contacts = 1, no contact details
  std::vector<std::pair<long, long>> pairs;
};

static bool pairs_callback(Object* o1, Object* o2, void* data) {
  auto* d = static_cast<PairsData*>(data);
  fcl::CollisionResult<S> result;
  if (fcl::collide(o1, o2, d->request, result) > 0) {
    long i = index_of(o1), j = index_of(o2);
    d->pairs.emplace_back(std::min(i, j), std::max(i, j));
  }
  return false;  // never stop: every colliding pair
}

struct NearestData {
  fcl::DistanceRequest<S> request;
  S best = std::numeric_limits<S>::max();
  long i = -1, j = -1;
};

static bool nearest_callback(Object* o1, Object* o2, void* data, S& dist) {
  auto* d = static_cast<NearestData*>(data);
  fcl::DistanceResult<S> result;
  fcl::distance(o1, o2, d->request, result);
  if (result.min_distance < d->best) {
    d->best = result.min_distance;
    d->i = std::min(index_of(o1), index_of(o2));
    d->j = std::max(index_of(o1), index_of(o2));
  }
  dist = d->best;  // the manager prunes pairs whose boxes are farther than this
  return d->best <= 0;
}

// ---- timing ------------------------------------------------------------------------------

struct Timing {
  double best = 1e300, sum = 0.0;
  int n = 0;
  void add(double ms) { best = std::min(best, ms); sum += ms; ++n; }
  double mean() const { return n ? sum / n : 0.0; }
};

template <class F> static double millis(F f) {
  auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

static void set_poses(std::vector<std::unique_ptr<Object>>& objs, const std::vector<Entry>& scene) {
  for (size_t k = 0; k < objs.size(); ++k) {
    objs[k]->setTransform(scene[k].pose);
    objs[k]->computeAABB();
  }
}

static void print_pairs(const char* key, std::vector<std::pair<long, long>> pairs) {
  std::sort(pairs.begin(), pairs.end());
  std::printf(", \"%s\": [", key);
  for (size_t k = 0; k < pairs.size(); ++k) std::printf("%s[%ld,%ld]", k ? "," : "", pairs[k].first, pairs[k].second);
  std::printf("]");
}

int main(int argc, char** argv) try {
  std::string scene_path, moved_path;
  int repeat = 5;
  bool list = false;
  for (int a = 1; a < argc; ++a) {
    std::string arg = argv[a];
    if (arg == "--moved" && a + 1 < argc) moved_path = argv[++a];
    else if (arg == "--repeat" && a + 1 < argc) repeat = std::max(1, std::atoi(argv[++a]));
    else if (arg == "--pairs") list = true;
    else if (scene_path.empty() && arg[0] != '-') scene_path = arg;
    else {
      std::cerr << "usage: " << argv[0] << " SCENE [--moved MOVED] [--repeat R] [--pairs]\n";
      return 2;
    }
  }
  if (scene_path.empty()) {
    std::cerr << "usage: " << argv[0] << " SCENE [--moved MOVED] [--repeat R] [--pairs]\n";
    return 2;
  }
  std::vector<Entry> scene = read_scene(scene_path), moved;
  if (!moved_path.empty()) {
    moved = read_scene(moved_path);
    if (moved.size() != scene.size()) fail(moved_path + ": not the same number of objects as " + scene_path);
  }

  std::map<std::string, std::shared_ptr<Model>> models;  // each mesh loaded once
  long triangles = 0;
  std::vector<std::unique_ptr<Object>> objs;
  auto load_start = std::chrono::steady_clock::now();
  for (size_t k = 0; k < scene.size(); ++k) {
    auto& model = models[scene[k].mesh];
    if (!model) model = load_model(scene[k].mesh);
    triangles += model->num_tris;
    objs.emplace_back(new Object(model, scene[k].pose));
    objs.back()->setUserData(reinterpret_cast<void*>(static_cast<intptr_t>(k)));
  }
  double load_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - load_start).count();
  std::vector<Object*> raw;
  for (auto& o : objs) raw.push_back(o.get());

  Timing build, pairs_t, move_t, nearest_t;
  std::unique_ptr<fcl::DynamicAABBTreeCollisionManager<S>> manager;
  for (int r = 0; r < repeat; ++r) {
    manager.reset();
    auto m = std::make_unique<fcl::DynamicAABBTreeCollisionManager<S>>();
    build.add(millis([&] {
      m->registerObjects(raw);
      m->setup();
    }));
    manager = std::move(m);
  }

  PairsData pairs;
  for (int r = 0; r < repeat; ++r) {
    PairsData d;
    pairs_t.add(millis([&] { manager->collide(&d, pairs_callback); }));
    pairs = std::move(d);
  }

  PairsData pairs_moved;
  if (!moved.empty()) {
    for (int r = 0; r < repeat; ++r) {
      set_poses(objs, scene);  // untimed: back to the first poses
      manager->update();
      PairsData d;
      move_t.add(millis([&] {
        set_poses(objs, moved);
        manager->update();
        manager->collide(&d, pairs_callback);
      }));
      pairs_moved = std::move(d);
    }
    set_poses(objs, scene);
    manager->update();
  }

  NearestData nearest;
  for (int r = 0; r < repeat; ++r) {
    NearestData d;
    nearest_t.add(millis([&] { manager->distance(&d, nearest_callback); }));
    nearest = d;
  }

  std::printf("{\"scene\": \"%s\", \"objects\": %zu, \"meshes\": %zu, \"triangles\": %ld, \"repeat\": %d",
              scene_path.c_str(), objs.size(), models.size(), triangles, repeat);
  std::printf(", \"pairs\": %zu", pairs.pairs.size());
  if (!moved.empty()) std::printf(", \"pairs_moved\": %zu", pairs_moved.pairs.size());
  if (list) {
    print_pairs("pairs_list", pairs.pairs);
    if (!moved.empty()) print_pairs("pairs_moved_list", pairs_moved.pairs);
  }
  std::printf(", \"millis_load\": %.3f", load_ms);
  std::printf(", \"millis_build\": %.3f, \"millis_build_mean\": %.3f", build.best, build.mean());
  std::printf(", \"millis_pairs\": %.3f, \"millis_pairs_mean\": %.3f", pairs_t.best, pairs_t.mean());
  if (!moved.empty())
    std::printf(", \"millis_move_and_pairs\": %.3f, \"millis_move_and_pairs_mean\": %.3f", move_t.best, move_t.mean());
  std::printf(", \"millis_nearest\": %.3f, \"millis_nearest_mean\": %.3f", nearest_t.best, nearest_t.mean());
  std::printf(", \"nearest\": [%ld, %ld, %.17g]}\n", nearest.i, nearest.j, nearest.best);
  return 0;
} catch (const std::exception& e) {
  std::cerr << "fcl_scene: " << e.what() << "\n";
  return 1;
}
