/*
 * stop.c: asking a caller's stop. See stop.h.
 */
#include "core/base/stop.h"

#include <stddef.h>

int facet_stop_requested(const struct facet_stop *stop)
{
    return stop != NULL && stop->requested != NULL &&
           stop->requested(stop->context) != 0;
}

int facet_stop_error(struct facet_error *err)
{
    return facet_error_set(err, FACET_ESTOP, "stopped on request");
}

int facet_stop_check(const struct facet_stop *stop, struct facet_error *err)
{
    return facet_stop_requested(stop) ? facet_stop_error(err) : FACET_OK;
}
