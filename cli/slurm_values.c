/*
 * slurm_values.c: the values of #SBATCH lines. See slurm_values.h.
 */
#include "slurm_values.h"

#include <string.h>
#include <strings.h>

#include "core/base/text.h"

/* A letter, digit, '_', '-' or '.': what a Slurm name is made of. */
static int name_char(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
           (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
}

int slurm_check_partition(const char *text, struct facet_error *err)
{
    int name = 0;
    for (const char *c = text;; c++) {
        if (*c == ',' || *c == '\0') {
            if (name == 0)
                break;
            if (*c == '\0')
                return FACET_OK;
            name = 0;
        } else if (name_char(*c)) {
            name++;
        } else {
            break;
        }
    }
    char shown[128];
    text_for_terminal(text, shown, sizeof shown);
    return facet_error_set(err, FACET_EINPUT,
        "--partition: '%s' is not a Slurm partition name (letters, digits, "
        "'_', '-' and '.', several separated by commas)", shown);
}

/* Reads a run of 1 to 9 digits at *c, moving past it; 0 when there is none. */
static int digits(const char **c)
{
    int n = 0;
    while (**c >= '0' && **c <= '9' && n < 10) {
        (*c)++;
        n++;
    }
    return n > 0 && n < 10;
}

int slurm_check_time(const char *text, struct facet_error *err)
{
    if (strcasecmp(text, "unlimited") == 0 ||
        strcasecmp(text, "infinite") == 0)
        return FACET_OK;
    const char *c = text;
    int fields = 1, ok = digits(&c);
    if (ok && *c == '-') {
        c++;
        ok = digits(&c);
    }
    while (ok && *c == ':' && fields < 3) {
        c++;
        ok = digits(&c);
        fields++;
    }
    if (ok && *c == '\0')
        return FACET_OK;
    char shown[128];
    text_for_terminal(text, shown, sizeof shown);
    return facet_error_set(err, FACET_EINPUT,
        "--time: '%s' is not a Slurm time limit (MM, MM:SS, HH:MM:SS, "
        "DD-HH, DD-HH:MM, DD-HH:MM:SS or UNLIMITED)", shown);
}

int slurm_check_mem(const char *text, struct facet_error *err)
{
    const char *c = text;
    if (digits(&c) && strchr("KMGTkmgt", *c) != NULL && *c != '\0' &&
        c[1] == '\0')
        return FACET_OK;
    c = text;
    if (digits(&c) && *c == '\0')
        return FACET_OK;
    char shown[128];
    text_for_terminal(text, shown, sizeof shown);
    return facet_error_set(err, FACET_EINPUT,
        "--mem: '%s' is not a Slurm memory size (a whole number and K, M, G "
        "or T, e.g. 16G; M when none)", shown);
}

int slurm_check_name(const char *flag, const char *text,
                     struct facet_error *err)
{
    const char *c = text;
    while (name_char(*c))
        c++;
    if (c != text && *c == '\0')
        return FACET_OK;
    char shown[128];
    text_for_terminal(text, shown, sizeof shown);
    return facet_error_set(err, FACET_EINPUT,
        "%s: '%s' is not a Slurm name (letters, digits, '_', '-' and '.')",
        flag, shown);
}

/* The settings an extra line may not make: the sbatch option (long
 * name, short letter or 0) and, when facet slurm has a flag for it, that
 * flag. */
static const struct {
    const char *name;
    char letter;
    const char *flag;
} written[] = {
    {"partition", 'p', "--partition P"},
    {"time", 't', "--time T"},
    {"mem", 0, "--mem M"},
    {"account", 'A', "--account A"},
    {"qos", 'q', "--qos Q"},
    {"cpus-per-task", 'c', "--cpus C"},
    {"job-name", 'J', NULL},
    {"array", 'a', NULL},
    {"ntasks", 'n', NULL},
    {"output", 'o', NULL},
    {"dependency", 'd', NULL},
};

int slurm_check_sbatch_line(const char *line, int mem_given,
                            struct facet_error *err)
{
    char shown[160];
    text_for_terminal(line, shown, sizeof shown);
    for (const char *c = line; *c != '\0'; c++)
        if ((unsigned char)*c < 0x20 || *c == 0x7f)
            return facet_error_set(err, FACET_EINPUT,
                "--sbatch: '%s' holds a line break or another control "
                "character: give each #SBATCH line as its own --sbatch",
                shown);
    if (line[0] != '-' || line[1] == '\0' || line[1] == ' ')
        return facet_error_set(err, FACET_EINPUT,
            "--sbatch: '%s' is not an sbatch option (e.g. --sbatch "
            "'--gres=gpu:1'; it is written as #SBATCH LINE)", shown);
    const char *option = NULL;
    for (size_t k = 0; k < sizeof written / sizeof *written; k++) {
        if (line[1] == '-') {
            /* --name, --name=V, --name V, or a prefix of the name, which
             * sbatch takes for it when no other option shares it */
            size_t n = strcspn(line + 2, "= \t");
            if (n > 0 && n <= strlen(written[k].name) &&
                strncmp(line + 2, written[k].name, n) == 0)
                option = written[k].name;
            if (mem_given && n > 3 &&
                (strncmp(line + 2, "mem-per-cpu", n) == 0 ||
                 strncmp(line + 2, "mem-per-gpu", n) == 0))
                return facet_error_set(err, FACET_EINPUT,
                    "--sbatch: '%s' and --mem cannot both be given (sbatch "
                    "takes one memory request)", shown);
        } else if (written[k].letter != 0 && line[1] == written[k].letter) {
            option = written[k].name;
        }
        if (option == NULL)
            continue;
        if (written[k].flag != NULL)
            return facet_error_set(err, FACET_EINPUT,
                "--sbatch: '%s' sets --%s, which facet slurm writes from "
                "its own flag: give %s", shown, option, written[k].flag);
        return facet_error_set(err, FACET_EINPUT,
            "--sbatch: '%s' sets --%s, which the scripts set themselves "
            "(the array of shards, a task each, their logs and the "
            "merge's wait for them)", shown, option);
    }
    return FACET_OK;
}
