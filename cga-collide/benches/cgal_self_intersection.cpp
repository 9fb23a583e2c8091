// CGAL's self-intersection test on the same meshes as `cargo bench --bench distance --
// self_intersection`, for the comparison in docs/distance.md. Build and run with
// `bash cga-collide/benches/cgal_self_intersection.sh` (needs Debian's libcgal-dev).
//
// Usage: cgal_self_intersection MESH.(off|obj) REPEAT
// Prints the mesh size, the number of self-intersecting face pairs, and the best and mean
// times of `does_self_intersect` (first hit) and `self_intersections` (every pair).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Face = boost::graph_traits<Mesh>::face_descriptor;
namespace PMP = CGAL::Polygon_mesh_processing;

template <class F> static void timed(const char* name, int repeat, F f) {
  double best = 1e300, sum = 0.0;
  for (int r = 0; r < repeat; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    f();
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    best = std::min(best, ms);
    sum += ms;
  }
  std::cout << name << ": best " << best << " ms, mean " << sum / repeat << " ms over " << repeat << "\n";
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: " << argv[0] << " MESH REPEAT\n";
    return 2;
  }
  Mesh mesh;
  if (!CGAL::IO::read_polygon_mesh(argv[1], mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "cannot read a triangle mesh from " << argv[1] << "\n";
    return 1;
  }
  int repeat = std::atoi(argv[2]);
  std::cout << argv[1] << ": " << num_faces(mesh) << " triangles\n";
  bool any = false;
  timed("does_self_intersect", repeat, [&] { any = PMP::does_self_intersect(mesh); });
  std::vector<std::pair<Face, Face>> pairs;
  timed("self_intersections", repeat, [&] {
    pairs.clear();
    PMP::self_intersections(mesh, std::back_inserter(pairs));
  });
  std::cout << "self-intersecting: " << (any ? "yes" : "no") << ", pairs: " << pairs.size() << "\n";
  return 0;
}
