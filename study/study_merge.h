/*
 * study_merge.h: joining the shards of a run spread over machines (each
 * made by a study with a shard I/N, core/search/shard.h, into its own
 * database) into the one run a single machine would have made.
 *
 * The merge reads every shard file (never writing to one), checks that
 * they are shards of one run (the same surface, by SHA-256, and the same
 * settings; their index told apart), unions their options, and ranks the
 * union as every run is ranked at its end (study_finish): fronts,
 * crowding, hypervolume, knee, and the panels of the options the run
 * keeps, when its surface can be found. Exhaustive and random shards keep
 * the numbers their options have in the unsharded run, so the merge of all
 * of them is that run option for option and rank for rank; NSGA-II
 * islands are numbered in shard order, a point met by two islands once.
 *
 * The output file is written whole or not at all: the merge works on a
 * copy beside it (the file as it was, or a new one) and puts the copy in
 * its place at the end (rename). The merged run is found again by its
 * settings, so merging the same shards twice changes nothing, and merging
 * again with a shard that was missing completes the run in place.
 */
#ifndef FACET_STUDY_MERGE_H
#define FACET_STUDY_MERGE_H

#include "study/study.h"

/* What a merge did. */
struct merge_report {
    int64_t run;              /* the merged run's id in the output */
    int shard_count;          /* N of the shards' I/N */
    int shards_merged;        /* how many of them were given */
    char missing[200];        /* the indices not given ("3, 5"), "" when
                                 none; cut with "..." when long */
    int64_t options;          /* options of the merged run */
    int64_t pareto_options;
    int replaced;             /* 1 when the output held the run already */
};

/* Merges the shard files shards[0..nshards) into out (created when it
 * does not exist; other runs in it are kept). hooks: stage and warning
 * (NULL: not told). FACET_EINPUT with a one-line message for a file that
 * is not a Facet database or holds no finished shard, shards of different
 * runs (naming the first setting that differs), a shard given twice, an
 * output that is one of the shards, or an output folder that cannot be
 * written; out is then as it was. Shards missing from the run make it
 * incomplete (report->missing), which is not an error. A run out holds
 * already, merged from more shards than given now, is not replaced by the
 * fewer (FACET_EINPUT, naming both counts) unless allow_fewer: merging
 * again after the shard files were cleaned up must not make a complete run
 * incomplete. */
int study_merge(const char *out, const char *const *shards, int nshards,
                int allow_fewer, const struct study_hooks *hooks,
                struct merge_report *report, struct facet_error *err);

#endif
