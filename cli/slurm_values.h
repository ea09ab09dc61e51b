/*
 * slurm_values.h: the values facet slurm writes into #SBATCH lines,
 * checked before a script is written.
 *
 * An #SBATCH line takes no shell quoting: Slurm reads it up to its end
 * and splits it at blanks. A value that held a newline would put a shell
 * command before the script's own first line, one that held a blank would
 * add options of its own. So each value is held to the words Slurm
 * takes for it, and refused in one line (FACET_EINPUT) otherwise; the
 * message names the flag and the value, cleaned for the terminal.
 */
#ifndef FACET_SLURM_VALUES_H
#define FACET_SLURM_VALUES_H

#include "core/base/error.h"

/* --partition: a partition name, or several separated by commas. */
int slurm_check_partition(const char *text, struct facet_error *err);

/* --time: MM, MM:SS, HH:MM:SS, DD-HH, DD-HH:MM, DD-HH:MM:SS, UNLIMITED. */
int slurm_check_time(const char *text, struct facet_error *err);

/* --mem: a whole number, then K, M, G or T (sbatch's default unit is M). */
int slurm_check_mem(const char *text, struct facet_error *err);

/* --account, --qos (flag names which): one name of letters, digits, '_',
 * '-' and '.'. */
int slurm_check_name(const char *flag, const char *text,
                     struct facet_error *err);

/* --sbatch: one extra line, written "#SBATCH LINE": an sbatch option
 * (it starts with '-'), no control character (a newline would end the
 * comment), and not one of the settings the scripts write themselves
 * (the array, its tasks and CPUs, the logs, the job names, the merge's
 * dependency) nor one facet slurm has a flag for (--partition, --time,
 * --mem, --account, --qos: the flag is named instead), whatever its
 * spelling (--name=V, --name V, -X V, -XV, or an abbreviation sbatch
 * would take for it). mem_given: --mem is given, so --mem-per-cpu and
 * --mem-per-gpu, which sbatch refuses beside it, are refused here. */
int slurm_check_sbatch_line(const char *line, int mem_given,
                            struct facet_error *err);

#endif
