/*
 * complete.c: file path completion. See complete.h.
 */
#include "complete.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

static int is_obj(const char *name)
{
    size_t n = strlen(name);
    return n > 4 && strcasecmp(name + n - 4, ".obj") == 0;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(a, b);
}

int tui_complete_path(const char *text, struct tui_completion *out)
{
    char path[sizeof out->text];  /* text may be out->text */
    snprintf(path, sizeof path, "%s", text);
    memset(out, 0, sizeof *out);
    snprintf(out->text, sizeof out->text, "%s", path);
    const char *slash = strrchr(path, '/');
    char dir[1024];
    const char *stem = slash ? slash + 1 : path;
    size_t dir_len = slash ? (size_t)(slash - path) + 1 : 0;
    if (dir_len >= sizeof dir)
        return 0;
    if (slash) {
        memcpy(dir, path, dir_len);
        dir[dir_len] = '\0';
    } else {
        snprintf(dir, sizeof dir, ".");
    }
    DIR *d = opendir(dir);
    if (d == NULL)
        return 0;
    size_t stem_len = strlen(stem);
    char common[TUI_COMPLETE_NAME] = "";
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        const char *name = e->d_name;
        if (strcmp(name, ".") == 0 || strcmp(name, "..") == 0 ||
            strncmp(name, stem, stem_len) != 0 ||
            (name[0] == '.' && stem[0] != '.') ||
            strlen(name) + 2 > TUI_COMPLETE_NAME)
            continue;
        char full[2048];
        snprintf(full, sizeof full, "%s%s", slash ? dir : "", name);
        struct stat st;
        int is_dir = stat(full, &st) == 0 && S_ISDIR(st.st_mode);
        if (!is_dir && !is_obj(name))
            continue;
        char entry[TUI_COMPLETE_NAME];
        size_t len = strlen(name);  /* < TUI_COMPLETE_NAME - 1, above */
        memcpy(entry, name, len);
        if (is_dir)
            entry[len++] = '/';
        entry[len] = '\0';
        if (out->count == 0) {
            snprintf(common, sizeof common, "%s", entry);
        } else {
            size_t k = 0;
            while (common[k] && common[k] == entry[k])
                k++;
            common[k] = '\0';
        }
        if (out->kept < TUI_COMPLETE_MAX)
            snprintf(out->name[out->kept++], TUI_COMPLETE_NAME, "%s", entry);
        out->count++;
    }
    closedir(d);
    qsort(out->name, (size_t)out->kept, sizeof out->name[0], by_name);
    if (out->count == 0)
        return 0;
    /* a lone directory's '/' is part of common already */
    if (strlen(common) > stem_len)
        snprintf(out->text, sizeof out->text, "%.*s%s", (int)dir_len, path,
                 common);
    return out->count;
}
