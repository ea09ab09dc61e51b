/*
 * objdump.c: prints what obj_load read from an OBJ file, for the
 * differential test against tinyobjloader (tests/e2e/diff_tinyobj.py).
 *
 *   objdump FILE
 *
 * Output, one record a line:
 *   vertices N / texcoords N / normals N / faces N / triangles N
 *   v X Y Z       every position, %.17g
 *   vt U V        every texture coordinate
 *   vn X Y Z      every normal
 *   t V/VT/VN x3  every triangle, 1-based indices, 0 for an absent one
 * Exits 0, or 2 with the error message on stderr.
 */
#include <stdio.h>

#include "core/obj/obj.h"

static unsigned long long one_based(uint32_t index)
{
    return index == OBJ_NONE ? 0 : (unsigned long long)index + 1;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: objdump FILE\n");
        return 2;
    }
    struct obj_file obj;
    struct facet_error err;
    if (obj_load(argv[1], &obj, &err) != FACET_OK) {
        fprintf(stderr, "objdump: %s\n", err.message);
        obj_free(&obj);
        return 2;
    }
    printf("vertices %zu\ntexcoords %zu\nnormals %zu\nfaces %zu\n"
           "triangles %zu\n", obj.nvertices, obj.ntexcoords, obj.nnormals,
           obj.nfaces, obj.ntriangles);
    for (size_t i = 0; i < obj.nvertices; i++)
        printf("v %.17g %.17g %.17g\n", obj.position[3 * i],
               obj.position[3 * i + 1], obj.position[3 * i + 2]);
    for (size_t i = 0; i < obj.ntexcoords; i++)
        printf("vt %.17g %.17g\n", obj.texcoord[2 * i],
               obj.texcoord[2 * i + 1]);
    for (size_t i = 0; i < obj.nnormals; i++)
        printf("vn %.17g %.17g %.17g\n", obj.normal[3 * i],
               obj.normal[3 * i + 1], obj.normal[3 * i + 2]);
    for (size_t t = 0; t < obj.ntriangles; t++) {
        const struct obj_corner *c = obj.corner + 3 * t;
        printf("t %llu/%llu/%llu %llu/%llu/%llu %llu/%llu/%llu\n",
               one_based(c[0].v), one_based(c[0].vt), one_based(c[0].vn),
               one_based(c[1].v), one_based(c[1].vt), one_based(c[1].vn),
               one_based(c[2].v), one_based(c[2].vt), one_based(c[2].vn));
    }
    obj_free(&obj);
    return fflush(stdout) == 0 ? 0 : 2;
}
