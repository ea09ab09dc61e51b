/*
 * cmd_slurm.c: `facet slurm SURFACE.obj [MORE.obj ...] --shards N --results
 * DIR [-- OPTIMIZE OPTIONS]`: the Slurm batch scripts of a run spread over
 * a cluster (of one surface, or of a project's files): a job array of N
 * shard tasks (facet optimize --shard I/N) and a merge job
 * that runs when every task has succeeded (afterok), and submit.sh, which
 * submits both.
 *
 * SQLite's WAL needs shared memory between the processes that open a
 * database, which network filesystems do not give: each task writes its
 * shard on the node's own disk ($TMPDIR, else /tmp) and copies the
 * finished file to the results folder (renamed into place, so the merge
 * never reads half a file); the merge job copies the shards to its own
 * disk, merges there, and copies the merged run back the same way.
 */
#include <assert.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "args.h"
#include "command.h"
#include "core/base/text.h"
#include "core/out/outfile.h"

/* What the scripts are made of. */
struct slurm_plan {
    char facet[PATH_MAX];        /* the facet binary, absolute */
    /* The surface, or a project's files, absolute: nsurfaces of them. */
    char (*surface)[PATH_MAX];
    int nsurfaces;
    char results[PATH_MAX];      /* absolute */
    char merged[256];            /* file name of the merged run */
    long shards, cpus;
    const char *partition, *time; /* NULL: the cluster's default */
    char **optimize;             /* the options given after "--" */
    int noptimize;
};

/* Writes text to out as one shell word, single-quoted. */
static void shell_word(FILE *out, const char *text)
{
    fputc('\'', out);
    for (const char *c = text; *c != '\0'; c++) {
        if (*c == '\'')
            fputs("'\\''", out);
        else
            fputc(*c, out);
    }
    fputc('\'', out);
}

/* The #SBATCH lines every job of the plan shares, then the start of its
 * script: strict mode, the binary and the results folder. */
static void job_common(FILE *out, const struct slurm_plan *p)
{
    if (p->partition != NULL)
        fprintf(out, "#SBATCH --partition=%s\n", p->partition);
    if (p->time != NULL)
        fprintf(out, "#SBATCH --time=%s\n", p->time);
    fputs("set -euo pipefail\nFACET=", out);
    shell_word(out, p->facet);
    fputs("\nRESULTS=", out);
    shell_word(out, p->results);
    fputc('\n', out);
}

static void write_shards(FILE *out, const struct slurm_plan *p)
{
    fprintf(out,
        "#!/bin/bash\n"
        "# Facet: shard I of %ld of one run, I = the array task (written by"
        "\n# facet slurm). Submit with submit.sh, which also submits the "
        "merge.\n"
        "#SBATCH --job-name=facet-shard\n"
        "#SBATCH --array=1-%ld\n"
        "#SBATCH --ntasks=1\n"
        "#SBATCH --cpus-per-task=%ld\n"
        "#SBATCH --output=%s/shard-%%a.log\n",
        p->shards, p->shards, p->cpus, p->results);
    job_common(out, p);
    fprintf(out,
        "I=$SLURM_ARRAY_TASK_ID\n"
        "# SQLite's WAL does not work over network filesystems: the shard"
        " is\n# written on the node's own disk and copied when finished.\n"
        "SCRATCH=$(mktemp -d \"${TMPDIR:-/tmp}/facet-shard-$I.XXXXXX\")\n"
        "trap 'rm -rf \"$SCRATCH\"' EXIT\n"
        "\"$FACET\" optimize");
    for (int k = 0; k < p->nsurfaces; k++) {
        fputc(' ', out);
        shell_word(out, p->surface[k]);
    }
    fprintf(out, " --db \"$SCRATCH/shard-$I.db\" --shard \"$I/%ld\" \\\n"
            "    --jobs \"${SLURM_CPUS_PER_TASK:-1}\" --table 5", p->shards);
    for (int k = 0; k < p->noptimize; k++) {
        fputc(' ', out);
        shell_word(out, p->optimize[k]);
    }
    fputs("\ncp \"$SCRATCH/shard-$I.db\" \"$RESULTS/.shard-$I.db.part\"\n"
          "mv \"$RESULTS/.shard-$I.db.part\" \"$RESULTS/shard-$I.db\"\n",
          out);
}

static void write_merge(FILE *out, const struct slurm_plan *p)
{
    fprintf(out,
        "#!/bin/bash\n"
        "# Facet: the merge of the %ld shards of one run (written by facet "
        "slurm);\n# submit.sh makes it wait for every shard (afterok).\n"
        "#SBATCH --job-name=facet-merge\n"
        "#SBATCH --ntasks=1\n"
        "#SBATCH --cpus-per-task=%ld\n"
        "#SBATCH --output=%s/merge.log\n", p->shards, p->cpus, p->results);
    job_common(out, p);
    fputs("MERGED=", out);
    shell_word(out, p->merged);
    fprintf(out,
        "\nSCRATCH=$(mktemp -d \"${TMPDIR:-/tmp}/facet-merge.XXXXXX\")\n"
        "trap 'rm -rf \"$SCRATCH\"' EXIT\n"
        "# Merged on this node's own disk, from copies of the shards; a\n"
        "# shard that is not there is named by facet merge, and the run\n"
        "# marked incomplete until it is merged in.\n"
        "shards=()\n"
        "for I in $(seq 1 %ld); do\n"
        "    if [ -f \"$RESULTS/shard-$I.db\" ]; then\n"
        "        cp \"$RESULTS/shard-$I.db\" \"$SCRATCH/shard-$I.db\"\n"
        "        shards+=(\"$SCRATCH/shard-$I.db\")\n"
        "    fi\n"
        "done\n"
        "if [ -f \"$RESULTS/$MERGED\" ]; then\n"
        "    cp \"$RESULTS/$MERGED\" \"$SCRATCH/$MERGED\"\n"
        "fi\n"
        "\"$FACET\" merge \"$SCRATCH/$MERGED\" \"${shards[@]}\"\n"
        "cp \"$SCRATCH/$MERGED\" \"$RESULTS/.$MERGED.part\"\n"
        "mv \"$RESULTS/.$MERGED.part\" \"$RESULTS/$MERGED\"\n", p->shards);
}

static void write_submit(FILE *out, const struct slurm_plan *p)
{
    fputs("#!/bin/bash\n"
          "# Submits the shards of a Facet run as a job array, then their "
          "merge,\n# which waits for every shard to succeed (written by "
          "facet slurm).\nset -euo pipefail\ncd \"$(dirname \"$0\")\"\n"
          "RESULTS=", out);
    shell_word(out, p->results);
    fputs("\nmkdir -p \"$RESULTS\"\n"
          "array=$(sbatch --parsable facet-shards.sbatch)\n"
          "array=${array%%;*}\n"
          "merge=$(sbatch --parsable --dependency=afterok:\"$array\" "
          "facet-merge.sbatch)\n"
          "merge=${merge%%;*}\n"
          "echo \"shards: job $array; merge: job $merge (after every shard "
          "succeeds)\"\n"
          "echo \"results: $RESULTS\"\n", out);
}

/* Writes one script of the plan into folder/name. */
static int write_script(const char *folder, const char *name,
                        void (*body)(FILE *, const struct slurm_plan *),
                        const struct slurm_plan *plan,
                        struct facet_error *err)
{
    char path[PATH_MAX + 64];
    snprintf(path, sizeof path, "%s/%s", folder, name);
    struct outfile f;
    int rc = outfile_open(&f, path, 1, err);
    if (rc != FACET_OK)
        return rc;
    body(f.out, plan);
    rc = outfile_commit(&f, err);
    if (rc == FACET_OK && chmod(path, 0755) != 0)
        rc = facet_error_set(err, FACET_EWORK, "%s: %s", path,
                             strerror(errno));
    return rc;
}

/* path made absolute against the working folder (it may not exist). */
static int absolute(const char *path, char out[PATH_MAX], const char *what,
                    struct facet_error *err)
{
    char here[PATH_MAX];
    if (path[0] == '/') {
        if (strlen(path) >= PATH_MAX)
            return facet_error_set(err, FACET_EINPUT, "%s: path too long",
                                   what);
        snprintf(out, PATH_MAX, "%s", path);
    } else if (getcwd(here, sizeof here) == NULL ||
               snprintf(out, PATH_MAX, "%s/%s", here, path) >= PATH_MAX) {
        return facet_error_set(err, FACET_EINPUT, "%s: path too long", what);
    }
    /* #SBATCH lines take no quotes: a folder of such characters would be
     * cut there. */
    if (strpbrk(out, " \t\n%'\"\\") != NULL)
        return facet_error_set(err, FACET_EINPUT,
            "%s: '%s' has a space, quote, backslash or %% in it, which an "
            "#SBATCH line cannot hold: choose another folder", what, out);
    return FACET_OK;
}

/* --partition: a Slurm partition name or a comma-separated list of them,
 * which the #SBATCH line holds as it is (letters, digits, '_', '-', '.'). */
static int check_partition(const char *text, struct facet_error *err)
{
    int name = 0;
    for (const char *c = text;; c++) {
        if (*c == ',' || *c == '\0') {
            if (name == 0)
                break;
            if (*c == '\0')
                return FACET_OK;
            name = 0;
        } else if ((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') ||
                   (*c >= '0' && *c <= '9') || *c == '_' || *c == '-' ||
                   *c == '.') {
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

/* --time: a Slurm time limit, one of the forms sbatch takes: MM, MM:SS,
 * HH:MM:SS, DD-HH, DD-HH:MM, DD-HH:MM:SS, or UNLIMITED (INFINITE). */
static int check_time(const char *text, struct facet_error *err)
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

/* The options after "--", checked as facet optimize checks them, in the
 * call the shard script makes (its files, --db, --shard, --jobs and
 * --table, then the options): a script that every task would refuse is
 * not written. */
static int check_optimize_call(const struct slurm_plan *p,
                               struct facet_error *err)
{
    int most = 1 + p->nsurfaces + 8 + p->noptimize;
    char **argv = calloc((size_t)most + 1, sizeof *argv);
    if (argv == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    char shard[64];
    snprintf(shard, sizeof shard, "1/%ld", p->shards);
    int n = 0;
    argv[n++] = "optimize";
    for (int k = 0; k < p->nsurfaces; k++)
        argv[n++] = p->surface[k];
    argv[n++] = "--db";
    argv[n++] = "shard.db";
    argv[n++] = "--shard";
    argv[n++] = shard;
    argv[n++] = "--jobs";
    argv[n++] = "1";
    argv[n++] = "--table";
    argv[n++] = "5";
    for (int k = 0; k < p->noptimize; k++)
        argv[n++] = p->optimize[k];
    assert(n <= most);
    struct facet_error why;
    facet_error_clear(&why);
    int rc = optimize_args_check(n, argv, &why);
    free(argv);
    if (rc != FACET_OK)
        return facet_error_set(err, rc,
            "slurm: facet optimize would refuse the options after --, on "
            "every node: %s", why.message);
    return FACET_OK;
}

/* The optimize options the scripts set themselves. */
static int check_optimize_options(char **options, int n,
                                  struct facet_error *err)
{
    static const char *const own[] = {"--db", "--shard", "--resume",
                                      "--jobs", "-j", NULL};
    for (int k = 0; k < n; k++)
        for (int j = 0; own[j] != NULL; j++) {
            size_t len = strlen(own[j]);
            if (strncmp(options[k], own[j], len) == 0 &&
                (options[k][len] == '\0' || options[k][len] == '='))
                return facet_error_set(err, FACET_EINPUT,
                    "slurm: %s is the scripts' to set (each shard's "
                    "database, its index, its threads); leave it out",
                    own[j]);
        }
    return FACET_OK;
}

/* The options as given (pointing into argv), NULL or the default when
 * absent. */
struct slurm_args {
    const char *shards, *results, *cpus, *partition, *time, *facet;
    const char *merged, *folder;
};

static const struct arg_option slurm_options[] = {
    {"shards", 'n', ARG_STRING, offsetof(struct slurm_args, shards), "N",
     "shard tasks of the job array", NULL},
    {"results", 0, ARG_STRING, offsetof(struct slurm_args, results), "DIR",
     "where the shards and the merged run are copied: a folder every node "
     "sees (the work itself is done on each node's $TMPDIR or /tmp: "
     "SQLite's WAL does not work over network filesystems)", NULL},
    {"cpus", 0, ARG_STRING, offsetof(struct slurm_args, cpus), "C",
     "CPUs per task, facet's threads (default 1)", NULL},
    {"partition", 0, ARG_STRING, offsetof(struct slurm_args, partition), "P",
     "the Slurm partition (default: the cluster's)", NULL},
    {"time", 0, ARG_STRING, offsetof(struct slurm_args, time), "T",
     "time limit per task (e.g. 02:00:00)", NULL},
    {"facet", 0, ARG_STRING, offsetof(struct slurm_args, facet), "PATH",
     "facet on the nodes (default: this one)", NULL},
    {"merged", 0, ARG_STRING, offsetof(struct slurm_args, merged), "NAME",
     "the merged run's file in DIR (default merged.db)", NULL},
    {"output", 'o', ARG_STRING, offsetof(struct slurm_args, folder),
     "FOLDER", "where the scripts go (default: DIR)", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static int slurm_main(int argc, char **argv, struct facet_error *err)
{
    struct slurm_args a = {NULL, NULL, NULL, NULL, NULL, NULL, "merged.db",
                           NULL};
    const struct arg_table own = {slurm_options, &a};
    struct slurm_plan plan;
    memset(&plan, 0, sizeof plan);
    /* The options after "--" are facet optimize's, for every shard. */
    int split = argc;
    for (int k = 1; k < argc; k++)
        if (strcmp(argv[k], "--") == 0) {
            split = k;
            break;
        }
    const char *surface[PROJECT_FILES_MAX];
    int nsurfaces;
    int rc = args_parse_surfaces(split, argv, &own, NULL, surface,
                                 &nsurfaces, err);
    if (rc != FACET_OK)
        return rc;
    const char *shards = a.shards, *results = a.results, *cpus = a.cpus;
    const char *folder = a.folder, *facet = a.facet, *merged = a.merged;
    plan.partition = a.partition;
    plan.time = a.time;
    if (nsurfaces == 0)
        return facet_error_set(err, FACET_EINPUT,
            "slurm: name the surface (facet slurm SURFACE.obj [MORE.obj "
            "...] --shards N --results DIR [-- optimize options])");
    if (shards == NULL || results == NULL)
        return facet_error_set(err, FACET_EINPUT,
            "slurm: give --shards N and --results DIR (a folder every node "
            "sees)");
    if ((rc = args_int(shards, 1, 100000, "--shards", &plan.shards, err)))
        return rc;
    if (plan.partition && (rc = check_partition(plan.partition, err)))
        return rc;
    if (plan.time && (rc = check_time(plan.time, err)))
        return rc;
    plan.cpus = 1;
    if (cpus && (rc = args_int(cpus, 1, 4096, "--cpus", &plan.cpus, err)))
        return rc;
    if (strchr(merged, '/') != NULL || merged[0] == '\0' ||
        merged[0] == '.' || strpbrk(merged, " \t\n'\"\\%") != NULL)
        return facet_error_set(err, FACET_EINPUT,
            "--merged: '%s' is not a plain file name (e.g. merged.db)",
            merged);
    snprintf(plan.merged, sizeof plan.merged, "%s", merged);
    plan.optimize = argv + split + (split < argc);
    plan.noptimize = split < argc ? argc - split - 1 : 0;
    if ((rc = check_optimize_options(plan.optimize, plan.noptimize, err)))
        return rc;
    char place[PROJECT_FILES_MAX][PATH_MAX];
    plan.surface = place;
    plan.nsurfaces = nsurfaces;
    for (int k = 0; k < nsurfaces; k++)
        if (realpath(surface[k], place[k]) == NULL ||
            access(surface[k], R_OK))
            return facet_error_set(err, FACET_EINPUT, "%s: %s", surface[k],
                                   strerror(errno));
    if ((rc = check_optimize_call(&plan, err)))
        return rc;
    if ((rc = absolute(results, plan.results, "--results", err)))
        return rc;
    if (facet != NULL) {
        if ((rc = absolute(facet, plan.facet, "--facet", err)))
            return rc;
    } else {
        ssize_t n = readlink("/proc/self/exe", plan.facet,
                             sizeof plan.facet - 1);
        if (n <= 0)
            return facet_error_set(err, FACET_EINPUT,
                "slurm: cannot tell where this facet is; give --facet PATH");
        plan.facet[n] = '\0';
    }
    const char *into = folder ? folder : plan.results;
    if (mkdir(into, 0777) != 0 && errno != EEXIST)
        return facet_error_set(err, FACET_EINPUT, "%s: %s", into,
                               strerror(errno));
    if ((rc = write_script(into, "facet-shards.sbatch", write_shards, &plan,
                           err)) ||
        (rc = write_script(into, "facet-merge.sbatch", write_merge, &plan,
                           err)) ||
        (rc = write_script(into, "submit.sh", write_submit, &plan, err)))
        return rc;
    printf("%s/submit.sh submits %ld shard tasks (facet-shards.sbatch) and "
           "their merge (facet-merge.sbatch);\nthe merged run will be "
           "%s/%s\n", into, plan.shards, plan.results, plan.merged);
    return FACET_OK;
}

const struct command cmd_slurm = {
    .name = "slurm",
    .usage = "SURFACE.obj [MORE.obj ...] --shards N --results DIR\n"
             "       [--cpus C] [--partition P] [--time T] [--facet PATH]\n"
             "       [--merged NAME] [-o FOLDER] [-- OPTIMIZE OPTIONS]",
    .summary = "Write Slurm batch scripts that run a search as N shards "
               "and merge them.",
    .before = "",
    .options = slurm_options,
    .after =
        "  -- OPTIONS          facet optimize's options for every shard "
        "(the\n"
        "                      scripts set --db, --shard and --jobs)\n"
        "example:\n"
        "  facet slurm roof.obj --shards 16 --cpus 8 --results "
        "/shared/roof -- \\\n"
        "      --u 20:80 --v 35:120 --threshold 1:10:0.5\n"
        "  /shared/roof/submit.sh\n"
        "  facet slurm skin.obj --shards 8 --cpus 4 --results /shared/skin "
        "-- \\\n"
        "      --module 1.0:2.0x1.0:1.6 --threshold 2:6:2\n",
    .run = slurm_main,
};
