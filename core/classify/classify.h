/*
 * classify.h: naming, typing and pricing panels, and the option totals.
 *
 * The paper's CPMGC (Table 1) and MOGD rules, as DESIGN.md defines them:
 *   - a curvature counts as zero when |k| <= eps (widened by rounding, see
 *     CLASSIFY_ROUNDING); eps is fixed by the user or, by default, the
 *     curvature at which a panel of diameter d sags by the flatness
 *     threshold t: eps = 8 t / d^2 (never below 8 * 1e-9 / d, a sag of
 *     rounding size, so that t = 0 leaves a plane flat);
 *   - with that default eps, a curvature also counts as zero when the
 *     range the estimate knows it to (panel.h's k1_error, k2_error, from
 *     the curvature estimate's errors, curvature.h) holds 0: a curvature
 *     whose sign the estimate does not know is no curvature (issue
 *     29: the rims of a coarse cone read 1 % of its other curvature, and
 *     whole rows of developable surfaces were typed DP; at t = 0 all of
 *     them). A sphere or cylinder, which the fit follows exactly, is known
 *     exactly, and eps alone decides;
 *   - the signs of K and H come from k1 and k2 after that zeroing: K = 0
 *     when either is zero, H then has the sign of the other (so a ruled
 *     panel never turns flat), and K > 0 gives H the common sign (so the
 *     "umbilic noise" cell of Table 1, K > 0 with H = 0, cannot occur);
 *   - the saddle rule: K < 0 and |k1 + k2| / 2 <= eps, the two curvatures
 *     cancelling to within the zero tolerance; other K < 0 panels are
 *     feature curves on the side of the sign of k1 + k2;
 *   - flat -> FP, ruled -> SP, every other class -> DP; then a panel whose
 *     deviation from its best-fit plane is within t (plus rounding) is made
 *     FP whatever its class;
 *   - cost = area x price of the type; in the paper's MOGD mode SP area is
 *     priced as FP. An option's cost is summed from its areas per type, so
 *     that equal areas give bit-equal costs;
 *   - the total cost adds a cost per panel, per metre of joint and per
 *     mould (classify_price_terms), all 0 by default: the paper's model.
 * Every total a user sees is computed here, once.
 */
#ifndef FACET_CLASSIFY_H
#define FACET_CLASSIFY_H

#include <stddef.h>
#include <stdint.h>

#include "core/base/error.h"
#include "core/base/exact_sum.h"
#include "core/panel/panel.h"

/* The rounding allowance of every limit a panel is held to: a computed
 * measure within 1e-9 of its panel's scale of the limit meets it. The three
 * ways of building panels agree to that (docs/method.md: "Same panels,
 * three ways"), so a panel is never typed or judged by the order its sums were
 * taken in. Applied as:
 *   - the threshold rule: deviation <= t + 1e-9 d (d the panel's diameter);
 *   - the zero test: |k| <= eps (1 + 1e-9);
 *   - the size limit: largest panel <= limit (1 + 1e-9), so a 2 m x 2 m
 *     panel summed as 4.000000000000003 m^2 meets a 4 m^2 limit. */
#define CLASSIFY_ROUNDING 1e-9

struct classify_options {
    double threshold;          /* flatness threshold t (m); paper 0.003 */
    double curvature_tol;      /* eps (1/m); 0 means 8 t / d^2 per panel */
    double price[TYPE_COUNT];  /* USD/m^2 of FP, SP, DP */
    int sp_as_fp;              /* price SP area as FP (the paper's MOGD) */
    double max_panel_area;     /* feasibility limit (m^2) */
    /* The cost terms beyond area (0: the paper's model, area alone): */
    double panel_cost;              /* USD per panel, whatever its type */
    double joint_cost;              /* USD per metre of joint
                                       (joint_length.h) */
    double mould_cost[TYPE_COUNT];  /* USD per mould family of the type
                                       (a bending jig for SP, a mould for
                                       DP); FP needs none and is 0 */
    /* Panels as built (option.h; 0 everywhere: as built, no limits): */
    int sp_by_class;           /* 1: an SP panel is SP by its class alone,
                                  the paper's typing, whether or not a
                                  cylinder or cone fits it; 0: one that
                                  none fits within t is built and priced
                                  DP (a misfit) */
    double max_gap;            /* feasibility limit on the gap at every
                                  joint (m); 0 for none */
    double max_kink;           /* the same for the kink (rad); 0 for none */
    double min_panel_width;    /* feasibility limit on every panel's width
                                  (m, panel_width.h): a narrower panel is
                                  a sliver; 0 for none */
};

/* The paper's defaults: t = 3 mm, eps = 8 t / d^2, prices 701, 766, 1518,
 * SP priced as SP, the general 7.06 m^2 panel size limit. */
void classify_defaults(struct classify_options *options);

struct option_totals {
    size_t panels;
    size_t count[TYPE_COUNT];        /* panels per type */
    double area_of[TYPE_COUNT];      /* area per type (m^2) */
    double cost_of[TYPE_COUNT];      /* cost per type (USD) */
    size_t class_count[CLASS_COUNT];
    double class_area[CLASS_COUNT];  /* m^2 */
    double area;                     /* m^2, equals the mesh area */
    double cost;                     /* USD */
    double planarity;                /* sum of the deviations of the panels
                                        that are not DP (m): a DP panel is
                                        moulded to the design */
    double max_deviation;            /* largest of those deviations (m) */
    double max_panel_area;           /* m^2 */
    double p_dist;                   /* sum of the non-DP panels' P_dist
                                        (m^4) */
    int feasible;                    /* every panel within max_panel_area
                                        and no narrower than
                                        min_panel_width, and no joint over
                                        the gap or kink limit
                                        (classify_violation is 0) */
    /* Set by option_evaluate (option.h), 0 from classify_panels alone: */
    double joint_length;             /* m (joint_length.h) */
    size_t moulds;                   /* mould families, SP and DP (mould.h):
                                        an upper bound on the fewest */
    size_t moulds_of[TYPE_COUNT];    /* the same per type (FP: 0) */
    size_t largest_family;           /* panels of the largest family */
    size_t singleton_families;       /* families of one panel */
    /* The cost, term by term (USD); cost is their sum: */
    double area_cost;                /* cost_of summed: the paper's model */
    double panel_cost;               /* panels x panel cost */
    double joint_cost;               /* joint_length x joint cost */
    double mould_cost;               /* moulds per type x mould cost */
    /* Panels as built and their joints, set by option_evaluate (option.h),
     * 0 from classify_panels alone. In SI: the store keeps them in mm and
     * degrees (quantity.h's quantity_stored), the views show them so. */
    double max_gap;                  /* largest gap at a joint (m) */
    double mean_gap;                 /* mean over the joints (m) */
    double max_kink;                 /* largest kink (rad) */
    double mean_kink;                /* mean over the joints (rad) */
    size_t gaps_over;                /* joints whose gap exceeds max_gap
                                        (0 without a limit) */
    size_t kinks_over;               /* likewise for max_kink */
    size_t sp_misfits;               /* panels classed SP that no cylinder
                                        or cone fits within t */
    size_t sp_fitted;                /* SP panels fitted (built SP) */
    double sp_min_radius;            /* the smallest radius an SP panel is
                                        bent to (m, sp_fit.h's
                                        bending_radius); NaN when none is
                                        built SP */
    /* Slivers (docs/method.md): the smallest panel by area, by classify;
     * by width and the panels narrower than min_panel_width, set by
     * option_evaluate when it measures widths (NaN and TOTALS_UNKNOWN when
     * not). */
    double min_panel_area;           /* m^2 */
    double min_panel_width;          /* m (panel_width.h) */
    size_t slivers;                  /* panels narrower than the limit
                                        (0 without a limit) */
    /* The kind of option: 0 classified (the surface cut, never moved),
     * 1 planarized (its corners moved off the surface until its quads are
     * planar, core/planar/planar_option.h). What a planarization reached,
     * a planarized option's only; NaN for a classified one (stored NULL,
     * never 0): option_totals_classified. */
    int planarized;
    double closeness_reached;        /* largest distance of a corner from
                                        the design surface (m) */
    double closeness_mean;           /* mean over the corners (m) */
    double planarity_reached;        /* largest distance between a quad's
                                        diagonals over its longer diagonal */
    size_t planar_over;              /* quads over the planarity tolerance
                                        or with a corner beyond the
                                        closeness budget: a planarized
                                        option's limit, as gaps_over is a
                                        gap limit's (TOTALS_UNKNOWN for a
                                        classified option) */
    /* A building's seams (core/project/project_seams.h), measured with
     * its joints: NaN and TOTALS_UNKNOWN for a single surface, for a
     * building of one surface and where joints are not measured (stored
     * NULL, never 0). The gap and kink at a seam also count in max_gap
     * .. kinks_over above, the kink as what the panels add to the
     * design's crease. */
    size_t seams;                    /* pairs of surfaces that meet */
    double seam_length;              /* m */
    double seam_max_gap;             /* m; NaN without a seam joint */
    double seam_max_kink;            /* rad: added to the crease */
    double seam_max_crease;          /* rad: the design's own */
    size_t seam_gaps_over;           /* seam joints over max_gap */
    size_t seam_kinks_over;          /* whose added kink is over max_kink */
};

/* Marks totals as a classified option's: planarized 0, what a
 * planarization reaches NaN, and the seams not measured (a building's
 * totals measure them after). classify_totals and a building's totals
 * start with it. */
void option_totals_classified(struct option_totals *totals);

/* A count of struct option_totals that is not known: what the store reads
 * where its file holds NULL, for an option stored before Facet counted it
 * (the mould counts of a run stored before schema v5). A length, area or
 * cost not known is NaN. Never a number to show or sum: a table shows
 * "-", JSON null, CSV an empty field (totals_count turns it into NaN). */
#define TOTALS_UNKNOWN SIZE_MAX

/* count as a number: NaN when it is TOTALS_UNKNOWN. */
double totals_count(size_t count);

/* The class of curvatures k1 >= k2 (1/m) with zero tolerance eps (1/m). */
enum panel_class classify_curvature(double k1, double k2, double eps);

/* The same for curvatures k1[1] known to lie in [k1[0], k1[2]] and
 * k2[1] in [k2[0], k2[2]] (1/m; from panel.h's k1_error, k2_error): each
 * counts as zero within eps, and also where its range holds 0, as the
 * estimate does not know its sign; H's range is their mean's. Table 1's
 * one rule: classify_curvature is it for curvatures known exactly. */
enum panel_class classify_curvature_within(const double k1[3],
                                           const double k2[3], double eps);

/* FP for flat, SP for ruled, DP for every other class. */
enum panel_type panel_type_of_class(enum panel_class class);

/* "convex_feature_curve", "saddle", ..., as classify --json writes them. */
const char *panel_class_name(enum panel_class class);

/* "FP", "SP", "DP". */
const char *panel_type_name(enum panel_type type);

/* The zero tolerance for a panel: options->curvature_tol when set, else
 * 8 t / d^2 with d the panel's diameter (1/m). */
double classify_tolerance(const struct classify_options *options,
                          const struct panel *panel);

/* 1 when panel's deviation is within options->threshold, rounding
 * allowed (CLASSIFY_ROUNDING): the threshold rule. */
int classify_within_threshold(const struct classify_options *options,
                              const struct panel *panel);

/* How far (m^2) a largest panel of max_panel_area exceeds the size limit:
 * 0 when within it, rounding allowed (CLASSIFY_ROUNDING). Feasibility and
 * constraint-domination both read it. */
double classify_area_excess(double max_panel_area, double limit);

/* The FP panels of p that deviate more than options->threshold (rounding
 * allowed): flat by curvature, not by deviation, as on a mesh coarser than
 * its panels (coarse_mesh.h) or, with the mean shape operator, across an
 * inflection. *worst (when not NULL) receives the largest such deviation
 * (m, 0 when none). */
size_t classify_fp_over_threshold(const struct panelization *p,
                                  const struct classify_options *options,
                                  double *worst);

/* Classifies, types and prices every panel of p (K, H, curvature_tol,
 * class, type, price, cost) and sums the option's totals into *totals:
 * classify_types, then classify_totals. */
void classify_panels(struct panelization *p,
                     const struct classify_options *options,
                     struct option_totals *totals);

/* The first half of classify_panels: every panel's K, H, curvature_tol,
 * class and type (by class and the threshold rule), and p's threshold. */
void classify_types(struct panelization *p,
                    const struct classify_options *options);

/* The second half: prices every panel of p by its type (price, cost) and
 * sums the option's totals into *totals (cleared first): what a panel
 * retyped after classify_types (a misfit, option.h) is priced by. */
void classify_totals(struct panelization *p,
                     const struct classify_options *options,
                     struct option_totals *totals);

/* Prices totals' areas per type (area_of) by options' prices: cost_of,
 * and area_cost and cost their sum (the terms beyond area are
 * classify_price_terms'). classify_totals ends with it; a building's
 * totals, whose areas are its surfaces' summed, are priced by it too. */
void classify_price_areas(const struct classify_options *options,
                          struct option_totals *totals);

/* The sums behind an option's areas, planarity and P_dist, each
 * independent of the order of its terms (exact_sum.h), so that options
 * equal in exact arithmetic get bit-equal totals: over a surface's panels
 * (classify_totals). */
struct option_area_sums {
    struct exact_sum area_of[TYPE_COUNT];
    struct exact_sum class_area[CLASS_COUNT];
    struct exact_sum area, planarity, p_dist;
};

void option_area_sums_init(struct option_area_sums *sums);

/* Adds one panel: its area by type and class, and its deviation and
 * P_dist unless it is DP (which follows the surface). */
void option_area_sums_add_panel(struct option_area_sums *sums,
                                const struct panel *panel);

/* The sums, rounded once, into totals' area_of, class_area, area,
 * planarity and p_dist. */
void option_area_sums_value(const struct option_area_sums *sums,
                            struct option_totals *totals);

/* How far an option is from feasible (0: feasible): its largest panel's
 * excess over the size limit max_panel_area (m^2, classify_area_excess)
 * plus the joints over the gap limit and over the kink limit and the
 * slivers, the panels narrower than the width limit, each counted as 1
 * (totals' gaps_over, kinks_over and slivers, counted against the limits
 * when it was evaluated; 0 without limits). Feasibility and
 * constraint-domination both read it; without gap or kink limits it is
 * the area excess, to the bit. */
double classify_violation(const struct option_totals *totals,
                          double max_panel_area);

/* The limits an option can break, each a term of classify_violation, in
 * the order they are shown. */
enum classify_limit {
    LIMIT_PANEL_AREA,   /* largest panel over max_panel_area (m^2) */
    LIMIT_PANEL_WIDTH,  /* slivers: panels under min_panel_width (m) */
    LIMIT_GAP,          /* joints over max_gap */
    LIMIT_KINK,         /* joints over max_kink */
    LIMIT_PLANARIZE,    /* a planarized option's quads not planar, or off
                           the surface beyond its closeness budget */
    LIMIT_COUNT
};

/* Each limit's term of classify_violation into term[LIMIT_COUNT] (the
 * area excess in m^2; the slivers, gaps and kinks over, counted; 0 when
 * not measured), and the limits broken as a mask of 1u << limit: the one
 * place that names them, for whatever says why an option is infeasible
 * (the workbench, facet runs). 0 for a feasible option. */
unsigned classify_broken_limits(const struct option_totals *totals,
                                double max_panel_area,
                                double term[LIMIT_COUNT]);

/* Why panel of p (built by option_evaluate, or read back from the store)
 * is a misfit, in one line into text (size bytes): the flatness threshold
 * and its best cylinder's and cone's deviations (sp_fit.h's wording); ""
 * for a panel that is not one. */
void classify_misfit_reason(const struct panelization *p, size_t panel,
                            char *text, size_t size);

/* Prices the terms beyond area from totals' panels, joint_length and
 * moulds (options' panel, joint and mould costs) and sets totals->cost to
 * area_cost + panel_cost + joint_cost + mould_cost. With the terms at 0 the
 * cost is the area cost to the bit. */
void classify_price_terms(const struct classify_options *options,
                          struct option_totals *totals);

/* The ranges of the settings a user gives, the same in the CLI's flags
 * and the New-run form's fields (numparse_number): */
#define CLASSIFY_AMOUNT_MAX 1e9        /* USD: a price, a cost term; the
                                          least is 0 */
#define CLASSIFY_PANEL_AREA_MIN 1e-9   /* m^2: the panel size limit */
#define CLASSIFY_PANEL_AREA_MAX 1e9
#define CLASSIFY_PANEL_WIDTH_MIN 1e-6  /* m: the limit on a panel's width */
#define CLASSIFY_PANEL_WIDTH_MAX 1e6
#define CLASSIFY_MOULD_TOL_MAX_MM 1e6  /* mm: the mould tolerance; the
                                          least is 0 */
#define CLASSIFY_MAX_GAP_MIN_MM 1e-6   /* mm: the limit on a joint's gap */
#define CLASSIFY_MAX_GAP_MAX_MM 1e6
#define CLASSIFY_MAX_KINK_MIN_DEG 1e-9 /* degrees: the limit on its kink */
#define CLASSIFY_MAX_KINK_MAX_DEG 180
#define CLASSIFY_THRESHOLD_MAX_MM 1e6  /* mm: the flatness threshold, one
                                          or a range's; the least is 0 */

/* Parses "SP,DP", the cost of a mould of each curved type (USD, finite, 0
 * to CLASSIFY_AMOUNT_MAX), into mould_cost[TYPE_SP] and [TYPE_DP];
 * [TYPE_FP] is set to 0. FACET_EINPUT names the field what and the
 * text. */
int classify_mould_costs_parse(const char *text, const char *what,
                               double mould_cost[TYPE_COUNT],
                               struct facet_error *err);

/* Parses "701,766,1518", the prices of FP, SP and DP (USD/m^2, finite,
 * 0 to CLASSIFY_AMOUNT_MAX), into price. FACET_EINPUT names the field
 * what (the caller's name for it) and the text. */
int classify_prices_parse(const char *text, const char *what,
                          double price[TYPE_COUNT], struct facet_error *err);

/* Checks options for values no facade has (negative or non-finite
 * threshold, prices, limits). Returns FACET_OK or FACET_EINPUT. */
int classify_check_options(const struct classify_options *options,
                           struct facet_error *err);

#endif
