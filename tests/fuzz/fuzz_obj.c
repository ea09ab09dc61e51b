/*
 * fuzz_obj.c: the OBJ loader on any bytes: parsed, then built into a mesh
 * in metres; every input is either a surface or one FILE:LINE: error.
 */
#include <assert.h>
#include <string.h>

#include "core/surface/mesh.h"
#include "core/obj/obj.h"
#include "fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct obj_file obj;
    struct facet_error err;
    int rc = obj_parse((const char *)data, size, "fuzz.obj", &obj, &err);
    if (rc == FACET_OK) {
        struct mesh mesh;
        struct mesh_options options = {UNITS_MM, NULL, NULL};
        if (mesh_build(&obj, &options, &mesh, &err) == FACET_OK)
            assert(mesh.ntriangles == 0 || mesh.area >= 0);
        mesh_free(&mesh);
    } else {
        /* One line, never empty. */
        assert(err.message[0] != '\0' && strchr(err.message, '\n') == NULL);
    }
    obj_free(&obj);
    return 0;
}
