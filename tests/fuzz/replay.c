/*
 * replay.c: a fuzz target as a plain program, for `make check`: runs
 * LLVMFuzzerTestOneInput on every file of the directories given (the
 * target's seed corpus, and the inputs that once crashed it, kept as
 * regression tests), and prints one "ok"/"not ok" line per directory.
 * A failing input aborts, which the test runner reports.
 *
 *   replay_obj tests/fuzz/corpus/obj tests/fuzz/crashes/obj
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz.h"

static int replay_file(const char *path)
{
    FILE *in = fopen(path, "rb");
    if (in == NULL)
        return -1;
    size_t size = 0, capacity = 1 << 16;
    unsigned char *data = malloc(capacity);
    size_t n;
    while (data != NULL && (n = fread(data + size, 1, capacity - size, in)) > 0) {
        size += n;
        if (size == capacity) {
            unsigned char *grown = realloc(data, capacity * 2);
            if (grown == NULL) {
                free(data);
                data = NULL;
                break;
            }
            data = grown;
            capacity *= 2;
        }
    }
    fclose(in);
    if (data == NULL)
        return -1;
    LLVMFuzzerTestOneInput(data, size);
    free(data);
    return 0;
}

int main(int argc, char **argv)
{
    int failed = 0;
    for (int a = 1; a < argc; a++) {
        DIR *dir = opendir(argv[a]);
        if (dir == NULL)
            continue;  /* no crash inputs yet */
        size_t count = 0;
        struct dirent *e;
        while ((e = readdir(dir)) != NULL) {
            if (e->d_name[0] == '.')
                continue;
            char path[4096];
            snprintf(path, sizeof path, "%s/%s", argv[a], e->d_name);
            if (replay_file(path) != 0) {
                printf("not ok - %s: cannot read\n", path);
                failed = 1;
            }
            count++;
        }
        closedir(dir);
        printf("ok - %s: %zu inputs replayed\n", argv[a], count);
    }
    return failed;
}
