/*
 * temp_dir.c: a test's temporary directory. See temp_dir.h.
 */
#include "tests/support/temp_dir.h"

#include <stdio.h>
#include <stdlib.h>

int temp_dir_make(char *dir, size_t size, const char *name)
{
    int n = snprintf(dir, size, "/tmp/facet_%s_XXXXXX", name);
    if (n < 0 || (size_t)n >= size)
        return -1;
    return mkdtemp(dir) == NULL ? -1 : 0;
}

int temp_dir_remove(const char *dir)
{
    char command[600];
    int n = snprintf(command, sizeof command, "rm -rf '%s'", dir);
    if (n < 0 || (size_t)n >= sizeof command)
        return -1;
    return system(command) == 0 ? 0 : -1;
}
