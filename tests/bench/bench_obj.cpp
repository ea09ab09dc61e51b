/*
 * bench_obj.cpp: loads one OBJ file N times with Facet's obj_load and with
 * Debian's tinyobjloader (LoadObj, triangulate on) in turns, and prints the
 * median wall time of each and their ratio:
 *
 *   obj_load: 0.100 s  tinyobjloader (double): 0.640 s  ratio 6.4x
 *
 *   bench_obj FILE [N]     (N defaults to 5)
 *
 * Both loaders must read the same counts, or the comparison means nothing:
 * the program checks vertex and triangle counts and exits 1 if they differ.
 * Built by tests/bench/bench_obj.sh against BUILD/libfacet.a and the double
 * build of tinyobjloader (TINYOBJLOADER_USE_DOUBLE, libtinyobjloader_double:
 * Facet reads coordinates into doubles too, and the float build does less
 * work than Facet must). Taken in turns, so that load on the shared machine
 * falls on both alike; medians, as one slow run is the machine's, not the
 * loader's.
 */
#ifndef TINYOBJLOADER_USE_DOUBLE
#error "bench_obj compares against the double build: define TINYOBJLOADER_USE_DOUBLE"
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <tiny_obj_loader.h>

extern "C" {
#include "core/obj/obj.h"
}

static double seconds_since(std::chrono::steady_clock::time_point start)
{
    std::chrono::duration<double> d = std::chrono::steady_clock::now() - start;
    return d.count();
}

static double median(std::vector<double> t)
{
    std::sort(t.begin(), t.end());
    size_t n = t.size();
    return n % 2 ? t[n / 2] : (t[n / 2 - 1] + t[n / 2]) / 2;
}

int main(int argc, char **argv)
{
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: bench_obj FILE [N]\n");
        return 2;
    }
    const char *path = argv[1];
    int runs = argc == 3 ? std::atoi(argv[2]) : 5;
    if (runs < 1)
        runs = 1;

    std::vector<double> facet_times, tiny_times;
    size_t facet_vertices = 0, facet_triangles = 0;
    size_t tiny_vertices = 0, tiny_triangles = 0;

    for (int run = 0; run < runs; run++) {
        auto start = std::chrono::steady_clock::now();
        struct obj_file obj;
        struct facet_error err;
        if (obj_load(path, &obj, &err) != FACET_OK) {
            std::fprintf(stderr, "obj_load: %s\n", err.message);
            obj_free(&obj);
            return 2;
        }
        facet_times.push_back(seconds_since(start));
        facet_vertices = obj.nvertices;
        facet_triangles = obj.ntriangles;
        obj_free(&obj);

        start = std::chrono::steady_clock::now();
        tinyobj::attrib_t attrib;
        std::vector<tinyobj::shape_t> shapes;
        std::vector<tinyobj::material_t> materials;
        std::string warn, error;
        bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn,
                                   &error, path, nullptr, true);
        tiny_times.push_back(seconds_since(start));
        if (!ok) {
            std::fprintf(stderr, "tinyobjloader: %s\n", error.c_str());
            return 2;
        }
        tiny_vertices = attrib.vertices.size() / 3;
        tiny_triangles = 0;
        for (const auto &shape : shapes)
            tiny_triangles += shape.mesh.num_face_vertices.size();
    }
    double facet = median(facet_times), tiny = median(tiny_times);

    if (facet_vertices != tiny_vertices || facet_triangles != tiny_triangles) {
        std::fprintf(stderr, "loaders disagree: obj_load %zu v %zu triangles, "
                     "tinyobjloader %zu v %zu triangles\n", facet_vertices,
                     facet_triangles, tiny_vertices, tiny_triangles);
        return 1;
    }
    std::printf("obj_load: %.3f s  tinyobjloader (double): %.3f s  ratio "
                "%.1fx  (%zu vertices, %zu triangles, medians of %d)\n",
                facet, tiny, tiny / facet, facet_vertices, facet_triangles,
                runs);
    return 0;
}
