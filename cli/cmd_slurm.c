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
 *
 * What a site asks of a job goes in as given, checked (slurm_values.h):
 * --mem, --account, --qos, extra #SBATCH lines (--sbatch, repeatable) and
 * a setup line (--setup 'module load ...'), run by bash at the start of
 * every job, before facet; it is held in a single-quoted variable and
 * run with eval, so that whatever it holds the script stays a script.
 *
 * The merge waits for every shard (afterok): after a failed shard it
 * never starts. The failed shard's log and submit.sh's text say so, with
 * the scancel and sbatch commands that cancel it or run the shard and
 * the merge again; submit.sh records the job numbers in the results
 * folder (jobs) so that a shard's log can name them.
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
#include "shown.h"
#include "slurm_values.h"

/* What the scripts are made of. */
struct slurm_plan {
    char facet[PATH_MAX];        /* the facet binary, absolute */
    /* The surface, or a project's files, absolute: nsurfaces of them. */
    char (*surface)[PATH_MAX];
    int nsurfaces;
    char results[PATH_MAX];      /* absolute */
    char scripts[PATH_MAX];      /* where the scripts are, absolute */
    char merged[256];            /* file name of the merged run */
    long shards, cpus;
    /* NULL: the cluster's default */
    const char *partition, *time, *mem, *account, *qos;
    const struct arg_list *extra; /* more #SBATCH lines, as given */
    const char *setup;           /* a shell line run first, or NULL */
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

/* The #SBATCH lines every job of the plan shares (before any command:
 * sbatch reads none after one), then strict mode, the binary, the
 * results folder and the scripts' folder. */
static void job_head(FILE *out, const struct slurm_plan *p)
{
    if (p->partition != NULL)
        fprintf(out, "#SBATCH --partition=%s\n", p->partition);
    if (p->time != NULL)
        fprintf(out, "#SBATCH --time=%s\n", p->time);
    if (p->mem != NULL)
        fprintf(out, "#SBATCH --mem=%s\n", p->mem);
    if (p->account != NULL)
        fprintf(out, "#SBATCH --account=%s\n", p->account);
    if (p->qos != NULL)
        fprintf(out, "#SBATCH --qos=%s\n", p->qos);
    for (int k = 0; p->extra != NULL && k < p->extra->count; k++)
        fprintf(out, "#SBATCH %s\n", p->extra->item[k]);
    fputs("set -euo pipefail\nFACET=", out);
    shell_word(out, p->facet);
    fputs("\nRESULTS=", out);
    shell_word(out, p->results);
    fputs("\nSCRIPTS=", out);
    shell_word(out, p->scripts);
    fputc('\n', out);
}

/* The setup line, if any: held as one quoted word, run with eval, so
 * that no value can make the script other than a script. */
static void job_setup(FILE *out, const struct slurm_plan *p)
{
    if (p->setup == NULL)
        return;
    fputs("# The setup line (facet slurm --setup), as given; module systems\n"
          "# read variables that are not set, so -u is off while it runs.\n"
          "SETUP=", out);
    shell_word(out, p->setup);
    fputs("\nset +u\n"
          "eval \"$SETUP\" || {\n"
          "    status=$?\n"
          "    echo \"facet: the setup line failed (status $status): $SETUP\""
          " >&2\n"
          "    exit \"$status\"\n"
          "}\n"
          "set -u\n", out);
}

/* What a failed shard writes to its log: the merge will never start,
 * and the commands that cancel it, or run the shard and the merge again.
 * The merge's number is submit.sh's record (RESULTS/jobs: "ARRAY
 * MERGE"), when it is of this array. */
static void shard_failed(FILE *out, const struct slurm_plan *p)
{
    fprintf(out,
        "shard_failed() {\n"
        "    local status=$1 merge=MERGE jobs=\n"
        "    read -r jobs 2>/dev/null < \"$RESULTS/jobs\" || true\n"
        "    if [ -n \"$jobs\" ] && [ \"${jobs%%%% *}\" = \"${SLURM_ARRAY_JOB_ID:-}\" ]; then\n"
        "        merge=${jobs#* }\n"
        "    fi\n"
        "    {\n"
        "        echo \"facet: shard $I of %ld failed (status $status): the"
        " merge waits for every shard (afterok) and will never start.\"\n"
        "        [ \"$merge\" != MERGE ] ||\n"
        "            echo \"facet: MERGE below is the merge's job number,"
        " which submit.sh printed (squeue --me -n facet-merge).\"\n"
        "        echo \"facet: cancel the merge: scancel $merge\"\n"
        "        echo \"facet: or, the cause mended, run this shard and the"
        " merge after it again:\"\n"
        "        echo \"facet:   scancel $merge; a=\\$(sbatch --parsable"
        " --array=$I $(printf %%q \"$SCRIPTS/facet-shards.sbatch\"));"
        " sbatch --dependency=afterok:\\${a%%%%;*}"
        " $(printf %%q \"$SCRIPTS/facet-merge.sbatch\")\"\n"
        "    } >&2\n"
        "}\n"
        "trap 'status=$?; rm -rf \"${SCRATCH:-}\";"
        " [ \"$status\" -eq 0 ] || shard_failed \"$status\"' EXIT\n"
        "# Slurm's TERM (a time limit, scancel): bash ends once facet has\n"
        "# stopped, and the log says what it means for the merge.\n"
        "trap 'exit 143' TERM\n", p->shards);
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
    job_head(out, p);
    fputs("I=$SLURM_ARRAY_TASK_ID\n", out);
    shard_failed(out, p);
    job_setup(out, p);
    fputs("# SQLite's WAL does not work over network filesystems: the shard"
          " is\n# written on the node's own disk and copied when finished.\n"
          "SCRATCH=$(mktemp -d \"${TMPDIR:-/tmp}/facet-shard-$I.XXXXXX\")\n"
          "\"$FACET\" optimize", out);
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
    job_head(out, p);
    job_setup(out, p);
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
    fputs("\nSCRIPTS=", out);
    shell_word(out, p->scripts);
    fputs("\nmkdir -p \"$RESULTS\"\n"
          "array=$(sbatch --parsable \"$SCRIPTS/facet-shards.sbatch\")\n"
          "array=${array%%;*}\n"
          "merge=$(sbatch --parsable --dependency=afterok:\"$array\" "
          "\"$SCRIPTS/facet-merge.sbatch\")\n"
          "merge=${merge%%;*}\n"
          "# for a failed shard's log to name the merge\n"
          "echo \"$array $merge\" >\"$RESULTS/jobs\"\n"
          "echo \"shards: job $array; merge: job $merge (after every shard "
          "succeeds)\"\n"
          "echo \"results: $RESULTS\"\n"
          "echo \"if a shard fails, the merge never starts (the shard's log"
          " says so): cancel it:\"\n"
          "echo \"  scancel $merge\"\n"
          "echo \"or, the cause mended, run shard I and the merge after it "
          "again:\"\n"
          "echo \"  scancel $merge; a=\\$(sbatch --parsable --array=I "
          "$(printf %q \"$SCRIPTS/facet-shards.sbatch\")); sbatch "
          "--dependency=afterok:\\${a%%;*} "
          "$(printf %q \"$SCRIPTS/facet-merge.sbatch\")\"\n", out);
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

/* Makes folder and every missing folder above it (mkdir -p), then makes
 * sure it can be written into; what names it in a message ("--results").
 * FACET_EINPUT naming the folder and why: a file in the way, a parent
 * that cannot be written, a read-only filesystem. */
static int make_folder(const char *folder, const char *what,
                       struct facet_error *err)
{
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s", folder);
    size_t length = strlen(path);
    /* Each prefix that ends before a '/', then the whole. */
    for (size_t at = 1; at <= length; at++) {
        if (at < length && path[at] != '/')
            continue;
        char kept = path[at];
        path[at] = '\0';
        struct stat st;
        if (stat(path, &st) == 0) {
            if (!S_ISDIR(st.st_mode)) {
                char shown[PATH_MAX];
                text_for_terminal(path, shown, sizeof shown);
                return facet_error_set(err, FACET_EINPUT,
                    "%s: %s is a file, not a folder: it is in the way of "
                    "the folder to make", what, shown);
            }
        } else if (mkdir(path, 0777) != 0 && errno != EEXIST) {
            int why = errno;
            char shown[PATH_MAX];
            text_for_terminal(path, shown, sizeof shown);
            return facet_error_set(err, FACET_EINPUT,
                "%s: cannot make the folder %s: %s", what, shown,
                strerror(why));
        }
        path[at] = kept;
    }
    if (access(folder, W_OK | X_OK) != 0) {
        int why = errno;
        char shown[PATH_MAX];
        text_for_terminal(folder, shown, sizeof shown);
        return facet_error_set(err, FACET_EINPUT,
            "%s: cannot write into the folder %s: %s", what, shown,
            strerror(why));
    }
    return FACET_OK;
}

/* The node-local folder path lies in (/tmp, /var/tmp, /dev/shm, $TMPDIR),
 * written into under, or 0 when it lies in none. */
static int node_local(const char *path, char *under, size_t size)
{
    const char *fixed[] = {"/tmp", "/var/tmp", "/dev/shm"};
    char tmpdir[PATH_MAX] = "";
    const char *env = getenv("TMPDIR");
    if (env != NULL && env[0] == '/' && realpath(env, tmpdir) == NULL)
        snprintf(tmpdir, sizeof tmpdir, "%s", env);
    for (int k = 0; k < 4; k++) {
        const char *folder = k < 3 ? fixed[k] : tmpdir;
        size_t n = strlen(folder);
        while (n > 1 && folder[n - 1] == '/')
            n--;
        if (n <= 1)
            continue;
        if (strncmp(path, folder, n) == 0 &&
            (path[n] == '/' || path[n] == '\0')) {
            if (k < 3)
                snprintf(under, size, "%s", folder);
            else
                snprintf(under, size, "$TMPDIR (%.*s)", (int)n, folder);
            return 1;
        }
    }
    return 0;
}

/* A warning (stderr, one line) when path, a file the nodes read (what
 * says which), lies on this machine's own disk, where no other node
 * finds it. */
static void warn_node_local(const char *what, const char *path)
{
    char under[PATH_MAX + 16];
    if (!node_local(path, under, sizeof under))
        return;
    shown_line(stderr, "facet: warning: slurm: %s %s is under %s, this "
               "machine's own: the other nodes will not find it (put it "
               "where every node sees it)", what, path, under);
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
    const char *merged, *folder, *mem, *account, *qos, *setup;
    struct arg_list sbatch;
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
    {"mem", 0, ARG_STRING, offsetof(struct slurm_args, mem), "M",
     "memory per task, as sbatch --mem takes it (e.g. 16G; default: the "
     "cluster's)", NULL},
    {"account", 0, ARG_STRING, offsetof(struct slurm_args, account), "A",
     "the account charged (default: yours)", NULL},
    {"qos", 0, ARG_STRING, offsetof(struct slurm_args, qos), "Q",
     "the quality of service (default: the cluster's)", NULL},
    {"sbatch", 0, ARG_LIST, offsetof(struct slurm_args, sbatch), "LINE",
     "one more line for both scripts, written '#SBATCH LINE' (e.g. "
     "--sbatch '--gres=gpu:1'); again for each line; not a setting the "
     "scripts or the flags above write", NULL},
    {"setup", 0, ARG_STRING, offsetof(struct slurm_args, setup), "LINE",
     "a shell line every job runs first, before facet (e.g. 'module load "
     "gcc sqlite'); a job whose setup fails stops there", NULL},
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
    struct slurm_args a;
    memset(&a, 0, sizeof a);
    a.merged = "merged.db";
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
    plan.mem = a.mem;
    plan.account = a.account;
    plan.qos = a.qos;
    plan.extra = &a.sbatch;
    plan.setup = a.setup;
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
    if (plan.partition &&
        (rc = slurm_check_partition(plan.partition, err)))
        return rc;
    if (plan.time && (rc = slurm_check_time(plan.time, err)))
        return rc;
    if (plan.mem && (rc = slurm_check_mem(plan.mem, err)))
        return rc;
    if (plan.account &&
        (rc = slurm_check_name("--account", plan.account, err)))
        return rc;
    if (plan.qos && (rc = slurm_check_name("--qos", plan.qos, err)))
        return rc;
    for (int k = 0; k < a.sbatch.count; k++)
        if ((rc = slurm_check_sbatch_line(a.sbatch.item[k], plan.mem != NULL,
                                          err)))
            return rc;
    if (plan.setup && strpbrk(plan.setup, "\n\r") != NULL) {
        char shown[160];
        text_for_terminal(plan.setup, shown, sizeof shown);
        return facet_error_set(err, FACET_EINPUT,
            "--setup: '%s' holds a line break: give one line (commands "
            "joined with ';' or '&&')", shown);
    }
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
    if ((rc = make_folder(plan.results, "--results", err)))
        return rc;
    if (folder != NULL && (rc = make_folder(folder, "-o", err)))
        return rc;
    if (realpath(folder ? folder : plan.results, plan.scripts) == NULL)
        return facet_error_set(err, FACET_EINPUT, "%s: %s",
                               folder ? folder : plan.results,
                               strerror(errno));
    for (int k = 0; k < plan.nsurfaces; k++)
        warn_node_local(plan.nsurfaces > 1 ? "the surface file" :
                        "the surface", plan.surface[k]);
    char binary[PATH_MAX];
    warn_node_local("the facet binary", realpath(plan.facet, binary) ?
                    binary : plan.facet);
    warn_node_local("the results folder", plan.results);
    const char *into = plan.scripts;
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
             "       [--cpus C] [--partition P] [--time T] [--mem M]\n"
             "       [--account A] [--qos Q] [--sbatch LINE]... [--setup LINE]\n"
             "       [--facet PATH] [--merged NAME] [-o FOLDER]\n"
             "       [-- OPTIMIZE OPTIONS]",
    .summary = "Write Slurm batch scripts that run a search as N shards "
               "and merge them.",
    .before = "",
    .options = slurm_options,
    .passes_on = &cmd_optimize,
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
