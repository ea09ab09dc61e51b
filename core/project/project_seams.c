/*
 * project_seams.c: a building's seams and their joints. See
 * project_seams.h.
 */
#include "core/project/project_seams.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/project/seam_joints.h"

static int boxes_meet(const struct mesh *a, const struct mesh *b,
                      double weld)
{
    for (int d = 0; d < 3; d++)
        if (a->bbox_min[d] > b->bbox_max[d] + weld ||
            b->bbox_min[d] > a->bbox_max[d] + weld)
            return 0;
    return 1;
}

int project_seams_find(const struct project *project, double weld,
                       const struct facet_stop *stop,
                       struct project_seams *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    out->weld = weld;
    size_t capacity = 0;
    int rc = FACET_OK;
    size_t n = project->nsurfaces;
    for (size_t a = 0; rc == FACET_OK && a < n; a++)
        for (size_t b = a + 1; rc == FACET_OK && b < n; b++) {
            const struct surface *sa = &project->surfaces[a].surface;
            const struct surface *sb = &project->surfaces[b].surface;
            if (!boxes_meet(&sa->mesh, &sb->mesh, weld))
                continue;
            if ((rc = facet_stop_check(stop, err)) != FACET_OK)
                break;
            struct seam seam;
            rc = seam_find(&sa->mesh, &sa->curvature, &sb->mesh,
                           &sb->curvature, weld, PROJECT_SEAM_SPACING, &seam,
                           err);
            if (rc != FACET_OK)
                break;
            if (seam.nedges == 0) {
                seam_free(&seam);
                continue;
            }
            if (out->nseams == capacity) {
                size_t want = capacity ? 2 * capacity : 8;
                struct project_seam *grown =
                    realloc(out->seams, want * sizeof *grown);
                if (grown == NULL) {
                    seam_free(&seam);
                    rc = facet_error_set(err, FACET_EWORK,
                                         "out of memory for the seams");
                    break;
                }
                out->seams = grown;
                capacity = want;
            }
            out->seams[out->nseams++] = (struct project_seam){a, b, seam};
        }
    if (rc != FACET_OK)
        project_seams_free(out);
    return rc;
}

void project_seams_free(struct project_seams *seams)
{
    for (size_t k = 0; k < seams->nseams; k++)
        seam_free(&seams->seams[k].seam);
    free(seams->seams);
    memset(seams, 0, sizeof *seams);
}

int project_seams_keep(struct project *project, double weld,
                       const struct facet_stop *stop,
                       struct facet_error *err)
{
    if (project->seams != NULL) {
        project_seams_free(project->seams);
        free(project->seams);
        project->seams = NULL;
    }
    if (project->nsurfaces < 2)
        return FACET_OK;
    struct project_seams *seams = malloc(sizeof *seams);
    if (seams == NULL)
        return facet_error_set(err, FACET_EWORK,
                               "out of memory for the seams");
    int rc = project_seams_find(project, weld, stop, seams, err);
    if (rc != FACET_OK) {
        free(seams);
        return rc;
    }
    project->seams = seams;
    return FACET_OK;
}

/* The two sides of seam s: each surface's mesh, UV lookup and panels. */
static void seam_sides(const struct project *project,
                       const struct project_seam *s,
                       const struct panelization *const *panels,
                       struct seam_side *a, struct seam_side *b)
{
    const struct surface *sa = &project->surfaces[s->a].surface;
    const struct surface *sb = &project->surfaces[s->b].surface;
    *a = (struct seam_side){&sa->mesh, &sa->uv, panels[s->a]};
    *b = (struct seam_side){&sb->mesh, &sb->uv, panels[s->b]};
}

int project_seams_measure(const struct project *project,
                          const struct project_seams *seams,
                          const struct panelization *const *panels,
                          double max_gap, double max_kink,
                          struct seam_totals *out, struct facet_error *err)
{
    memset(out, 0, sizeof *out);
    double gaps = 0, added = 0;
    for (size_t k = 0; k < seams->nseams; k++) {
        const struct project_seam *s = &seams->seams[k];
        struct seam_side a, b;
        seam_sides(project, s, panels, &a, &b);
        struct seam_joints j;
        int rc = seam_joints_measure(&s->seam, &a, &b, max_gap, max_kink, &j,
                                     err);
        if (rc != FACET_OK)
            return rc;
        out->nseams++;
        out->length += s->seam.length;
        out->njoints += j.njoints;
        out->max_gap = fmax(out->max_gap, j.max_gap);
        out->max_added = fmax(out->max_added, j.max_added);
        out->max_crease = fmax(out->max_crease, j.max_crease);
        out->gaps_over += j.gaps_over;
        out->kinks_over += j.kinks_over;
        gaps += j.mean_gap * (double)j.njoints;
        added += j.mean_added * (double)j.njoints;
    }
    if (out->njoints > 0) {
        out->mean_gap = gaps / (double)out->njoints;
        out->mean_added = added / (double)out->njoints;
    }
    return FACET_OK;
}

int project_seams_joints(const struct project *project,
                         const struct project_seams *seams,
                         const struct panelization *const *panels,
                         struct building_seam_joint **out, size_t *n,
                         struct facet_error *err)
{
    *out = NULL;
    *n = 0;
    size_t capacity = 0;
    for (size_t k = 0; k < seams->nseams; k++) {
        const struct project_seam *s = &seams->seams[k];
        struct seam_side a, b;
        seam_sides(project, s, panels, &a, &b);
        struct seam_joint *joint;
        size_t count;
        int rc = seam_joints_list(&s->seam, &a, &b, &joint, &count, err);
        if (rc == FACET_OK && *n + count > capacity) {
            size_t want = 2 * (*n + count);
            struct building_seam_joint *grown =
                realloc(*out, want * sizeof *grown);
            if (grown == NULL)
                rc = facet_error_set(err, FACET_EWORK,
                                     "out of memory for %zu seam joints",
                                     *n + count);
            else {
                *out = grown;
                capacity = want;
            }
        }
        if (rc != FACET_OK) {
            free(joint);
            free(*out);
            *out = NULL;
            *n = 0;
            return rc;
        }
        for (size_t j = 0; j < count; j++)
            (*out)[(*n)++] = (struct building_seam_joint){k, s->a, s->b,
                                                          joint[j]};
        free(joint);
    }
    return FACET_OK;
}

int project_option_seam_joints(const struct project *project,
                               const struct project_option *option,
                               struct building_seam_joint **out, size_t *n,
                               struct facet_error *err)
{
    *out = NULL;
    *n = 0;
    if (project->seams == NULL)
        return FACET_OK;
    assert(option->nsurfaces == project->nsurfaces);
    const struct panelization **panels =
        malloc((option->nsurfaces ? option->nsurfaces : 1) * sizeof *panels);
    if (panels == NULL)
        return facet_error_set(err, FACET_EWORK, "out of memory");
    for (size_t s = 0; s < option->nsurfaces; s++)
        panels[s] = &option->surfaces[s].panels;
    int rc = project_seams_joints(project, project->seams, panels, out, n,
                                  err);
    free(panels);
    return rc;
}
