// A plain C++ driver around Kirsanov's exact MMP (the `geodesic_library` inside the gdist
// package), so that `bench_vs_gdist.py --peer cpp` times it as a whole process, as ours is
// timed: read an OBJ, propagate from one vertex over the whole mesh, write one distance per
// vertex (`inf` where none is reached). Built by `build_kirsanov.sh`, which fetches the
// library; nothing of it is kept in this repository.
//
// usage: kirsanov_driver MESH.obj SOURCE_VERTEX > distances.txt

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "geodesic_algorithm_exact.h"

// `v x y z` and `f a b c` lines (1-based, `a/t/n` forms allowed, negative indices from the
// end; an index of no vertex read so far is refused); anything else is skipped. Polygons are refused: the benchmark's meshes are triangles.
static bool read_obj(const char *path, std::vector<double> &points, std::vector<unsigned> &faces) {
    std::ifstream in(path);
    if (!in) {
        std::fprintf(stderr, "kirsanov_driver: cannot open %s\n", path);
        return false;
    }
    std::string line;
    unsigned number = 0;
    while (std::getline(in, line)) {
        ++number;
        std::istringstream words(line);
        std::string kind;
        if (!(words >> kind)) {
            continue;
        }
        if (kind == "v") {
            double x, y, z;
            if (!(words >> x >> y >> z)) {
                std::fprintf(stderr, "kirsanov_driver: %s:%u: bad vertex\n", path, number);
                return false;
            }
            points.insert(points.end(), {x, y, z});
        } else if (kind == "f") {
            std::vector<long> corners;
            std::string corner;
            while (words >> corner) {
                long i = std::strtol(corner.c_str(), nullptr, 10);
                long count = static_cast<long>(points.size() / 3);
                corners.push_back(i < 0 ? count + i : i - 1);
                if (corners.back() < 0 || corners.back() >= count) {
                    std::fprintf(stderr, "kirsanov_driver: %s:%u: no vertex %s\n", path, number,
                                 corner.c_str());
                    return false;
                }
            }
            if (corners.size() != 3) {
                std::fprintf(stderr, "kirsanov_driver: %s:%u: not a triangle\n", path, number);
                return false;
            }
            for (long c : corners) {
                faces.push_back(static_cast<unsigned>(c));
            }
        }
    }
    return true;
}

int main(int argc, char **argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: kirsanov_driver MESH.obj SOURCE_VERTEX\n");
        return 2;
    }
    std::vector<double> points;
    std::vector<unsigned> faces;
    if (!read_obj(argv[1], points, faces)) {
        return 1;
    }
    unsigned source = static_cast<unsigned>(std::strtoul(argv[2], nullptr, 10));
    if (source >= points.size() / 3) {
        std::fprintf(stderr, "kirsanov_driver: no vertex %u\n", source);
        return 1;
    }
    geodesic::Mesh mesh;
    mesh.initialize_mesh_data(points, faces);
    geodesic::GeodesicAlgorithmExact algorithm(&mesh);
    std::vector<geodesic::SurfacePoint> sources(1, geodesic::SurfacePoint(&mesh.vertices()[source]));
    algorithm.propagate(sources);
    std::string out;
    char number[32];
    for (unsigned i = 0; i < mesh.vertices().size(); ++i) {
        geodesic::SurfacePoint p(&mesh.vertices()[i]);
        double distance;
        algorithm.best_source(p, distance);
        if (distance >= geodesic::GEODESIC_INF) {
            out += "inf\n";
        } else {
            std::snprintf(number, sizeof number, "%.17g\n", distance);
            out += number;
        }
    }
    std::fwrite(out.data(), 1, out.size(), stdout);
    return 0;
}
