/*
 * cmd_merge.c: `facet merge OUT.db SHARD.db...`: the shards of a run made
 * on several machines (facet optimize --shard I/N) joined into one run.
 * The work is study/study_merge.h's; this file parses and reports.
 */
#include <stdio.h>
#include <stdlib.h>

#include "args.h"
#include "command.h"
#include "progress.h"
#include "shown.h"
#include "signals.h"
#include "study/study_merge.h"

/* The options as given, 0 when absent. */
struct merge_args {
    int fewer;
};

static const struct arg_option merge_options[] = {
    {"fewer", 0, ARG_FLAG, offsetof(struct merge_args, fewer), NULL,
     "replace a merged run in OUT.db with one of fewer shards (refused "
     "otherwise: its other shards' options would be lost)", NULL},
    {NULL, 0, ARG_FLAG, 0, NULL, NULL, NULL},
};

static int merge_main(int argc, char **argv, struct facet_error *err)
{
    struct merge_args a = {0};
    const struct arg_table own = {merge_options, &a};
    const char **path = malloc((size_t)(argc > 1 ? argc : 1) * sizeof *path);
    if (path == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    int count;
    int rc = args_parse(argc, argv, &own, NULL, path, argc, &count, err);
    if (rc == FACET_OK && count < 2)
        rc = facet_error_set(err, FACET_EINPUT,
            "merge: name the output and the shards (facet merge OUT.db "
            "SHARD.db...)");
    struct merge_report report;
    struct study_hooks hooks = {NULL, progress_show_stage, NULL,
                                signals_stop_hook, NULL, progress_show_warning,
                                NULL};
    if (rc == FACET_OK) {
        /* Ctrl-C or SIGTERM stops the merge between its steps: its side
         * file removed, OUT.db as it was. */
        signals_catch_stop();
        rc = study_merge(path[0], path + 1, count - 1, a.fewer, &hooks,
                         &report, err);
    }
    if (rc == FACET_ESTOP) {
        shown_line(stderr, "facet: merge interrupted; %s is as it was",
                   path[0]);
        free(path);
        return signals_stop_status();
    }
    if (rc == FACET_OK) {
        if (report.missing[0] != '\0')
            fprintf(stderr, "facet: warning: shard%s %s of %d missing: run "
                    "%lld is incomplete (merge again with %s to complete "
                    "it)\n", report.shards_merged + 1 < report.shard_count
                    ? "s" : "", report.missing, report.shard_count,
                    (long long)report.run, report.shards_merged + 1 <
                    report.shard_count ? "them" : "it");
        shown_line(stdout, "%s: run %lld %s from %d of %d shards: %lld "
               "options, %lld Pareto-optimal", path[0], (long long)report.run,
               report.replaced ? "merged again" : "merged",
               report.shards_merged, report.shard_count,
               (long long)report.options, (long long)report.pareto_options);
    }
    free(path);
    return rc;
}

const struct command cmd_merge = {
    .name = "merge",
    .usage = "OUT.db SHARD.db... [--fewer]",
    .summary = "Join the shards of a run (optimize --shard I/N) into one "
               "run.",
    .before = "  OUT.db is written whole or not at all (other runs in it "
              "are kept);\n"
              "  merging the same shards again changes nothing; a shard "
              "missing is\n"
              "  named, the run marked incomplete until it is merged in.\n",
    .options = merge_options,
    .after = "example:\n"
             "  facet merge all.db shard-1.db shard-2.db shard-3.db\n",
    .run = merge_main,
};
