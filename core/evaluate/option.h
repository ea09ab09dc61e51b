/*
 * option.h: one design option: its grid and settings (option_params), the
 * measures an evaluation may leave out (option_measure), and the mould
 * families given to its panels. Its evaluation is evaluate.h.
 */
#ifndef FACET_OPTION_H
#define FACET_OPTION_H

#include "core/classify/classify.h"
#include "core/panel/panel.h"

/* What an evaluation may leave out. It always classifies and types the
 * panels and sums their counts, areas, deviations and area costs; these
 * are the measures beyond that. A measure left out leaves its totals not
 * known (NaN, TOTALS_UNKNOWN: stored NULL, shown "not measured"), never 0,
 * and every other number as it would be: a run leaves out what none of its
 * objectives, constraints and prices read (option_measures_needed), and an
 * option a designer opens is measured in full. */
enum option_measure {
    /* SP panels built on fitted cylinders and cones: each panel's built
     * type, misfit and sp_deviation; sp_misfits, sp_fitted. Typing by fit
     * (not sp_by_class) cannot do without it. */
    OPTION_MEASURE_FITS = 1 << 0,
    /* Gap and kink at every joint of the panels as built: the panels'
     * worst, max_gap .. kinks_over. Needs FITS. */
    OPTION_MEASURE_JOINTS = 1 << 1,
    /* Mould families: each panel's mould, moulds .. singleton_families. */
    OPTION_MEASURE_MOULDS = 1 << 2,
    /* The length of the grid's joint lines: joint_length. */
    OPTION_MEASURE_JOINT_LENGTH = 1 << 3,
    /* Every panel's width (panel_width.h, from its outline:
     * panel_geometry.h, ten times an evaluation's own work and more):
     * min_panel_width, slivers. */
    OPTION_MEASURE_WIDTHS = 1 << 4,
    OPTION_MEASURE_ALL = (1 << 5) - 1
};

/* The measures as text, as the store keeps them: "fits,joints,moulds,
 * joint_length,widths" in that order, each present when its bit is, "" for none;
 * into out (OPTION_MEASURES_TEXT bytes). */
#define OPTION_MEASURES_TEXT 64
void option_measures_format(unsigned measures, char *out, size_t size);

/* The bits of text as option_measures_format writes it; a name it does
 * not know counts as every measure (a newer Facet's: nothing is taken as
 * not measured that might have been). */
unsigned option_measures_parse(const char *text);

/* The measures an option needs under classify's options (its typing, its
 * limits and its prices) when its objectives need objective_measures
 * besides (metric.h's metric_measures, or'ed): FITS when SP is typed by
 * fit or JOINTS are needed, JOINTS for a gap or kink limit, WIDTHS for a
 * width limit, MOULDS and JOINT_LENGTH for a price on them. */
unsigned option_measures_needed(const struct classify_options *classify,
                                unsigned objective_measures);

/* The measures totals hold: each whose quantities are known. */
unsigned option_totals_measures(const struct option_totals *totals);

/* Copies into *totals the quantities of each measure it does not hold
 * that measured holds (the same option measured in full), leaving every
 * number it holds as it is: an option a run measured for what it reads,
 * measured in full when a designer opens it. Its price terms and cost do
 * not change: a run measures what it prices. */
void option_totals_fill(struct option_totals *totals,
                        const struct option_totals *measured);

struct option_params {
    int nu, nv;                          /* grid */
    unsigned unmeasured;                 /* option_measure bits left out;
                                            0 (a zeroed struct): none */
    enum panel_curvature_mode mode;      /* how panels take curvature */
    struct classify_options classify;    /* threshold, eps, prices, limit,
                                            cost terms */
    int mould_tol_given;                 /* 0: a mould family's tolerance is
                                            the option's flatness threshold
                                            (so a zeroed struct means it) */
    double mould_tol;                    /* else this (m) */
    int mould_mirror;                    /* mirror images share a mould */
};

/* The mould family settings of params (mould.h): its tolerance, or the
 * option's flatness threshold when none was given, and its mirrors. */
struct mould_options option_mould_options(const struct option_params *params);

/* The paper's defaults: classify_defaults, panels taking the extremes of
 * their samples, no grid (0 x 0: set it with option_params_at), mould
 * tolerance the flatness threshold, no mirrors. */
void option_params_defaults(struct option_params *params);

/* base with the grid nu x nv and the flatness threshold threshold_mm, a
 * length in millimetres as the designer, the design space and the store
 * write it, set in classify's metres (threshold_mm / 1000): the one place
 * a design point becomes the parameters its evaluation takes. */
struct option_params option_params_at(const struct option_params *base,
                                      int nu, int nv, double threshold_mm);

struct mould_families;

/* Gives panels (classified, unmoulded: evaluate.h) their moulds from
 * families, found over a list of panels in which panel k of panels is
 * number first + k (mould.h: 0 for a surface's own families, its offset
 * among a building's), and sets totals' mould counts to those of the
 * families its panels start, a family starting at its first panel (its
 * representative): moulds, moulds_of, largest_family and
 * singleton_families (the size of a family is over every part). Then
 * re-prices totals (classify_price_terms). For a surface's own families
 * every family starts on it, so these are the families' own counts. */
void option_moulds_set(const struct option_params *params,
                       const struct mould_families *families, size_t first,
                       struct panelization *panels,
                       struct option_totals *totals);

#endif
