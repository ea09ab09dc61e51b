#!/usr/bin/env bash
# front_panels.sh: which Pareto options' panels a run stores when it ends
# (issue 18: an NSGA-II run spent 45 % of its time storing the panels of
# its 1,155 Pareto options). A front within the budget, max(16, options /
# 40), is stored whole; a larger one stores the knee, then the ends of the
# front (infinite crowding), then the largest crowding distance, the
# order SQLite gives below; the others' panels are computed when first
# looked at, and then stored.
# layers: study store cli
. "$(dirname "$0")/lib.sh"

fixture roof.obj || exit 1
q() { sqlite3 "$WORK/f.db" "$1"; }

# The paper's study: 336 options, a front of about a dozen: all stored
# (the fixture paper.db: --u 20:40 --v 35:50 --threshold 3 --sp-as-fp
# --max-panel-area 1.92 --sp-fit no).
expect_fixture "the paper's study runs" 0 paper.db "$WORK/f.db"
front=$(q "select count(*) from options where run = 1 and rank = 1")
if [ "$front" -gt 16 ]; then
    echo "not ok - the paper's front ($front) is within the least budget, 16"
fi
same "a front of $front (at most 16) is stored whole" \
    "$(q "select count(*) from panel_sets where run = 1")" "$front"

# NSGA-II over a continuous threshold: a front larger than its budget.
expect "an NSGA-II run over t 1:5 mm runs" 0 "$FACET" optimize \
    "$WORK/roof.obj" --db "$WORK/f.db" --method nsga2 --pop 40 --gens 18 \
    --threshold 1:5
options=$(q "select count(*) from options where run = 2")
front=$(q "select count(*) from options where run = 2 and rank = 1")
budget=$((options / 40 > 16 ? options / 40 : 16))
if [ "$front" -le "$budget" ]; then
    echo "not ok - the NSGA-II front ($front) outgrows its budget ($budget): make the run larger"
fi
same "the run's row counts its options ($options, SQLite)" \
    "$(q "select options from runs where id = 2")" "$options"
same "$budget of the $front Pareto options' panels are stored (max(16, $options / 40))" \
    "$(q "select count(*) from panel_sets where run = 2")" "$budget"
want=$(q "select group_concat(number) from (select number from options
          where run = 2 and rank = 1 order by knee desc,
          crowding is null desc, crowding desc, number limit $budget)")
got=$(q "select group_concat(option) from (select option from panel_sets
         where run = 2 order by option)")
sorted() { tr , '\n' <<<"$1" | sort -n | paste -sd, -; }
same "they are the knee, the front's ends, then the largest crowding" \
    "$(sorted "$got")" "$(sorted "$want")"
same "the knee is among them" \
    "$(q "select count(*) from panel_sets s join options o on o.run = s.run
          and o.number = s.option where s.run = 2 and o.knee")" 1

# A Pareto option not stored: computed when first looked at, then stored.
other=$(q "select number from options where run = 2 and rank = 1 and
           number not in (select option from panel_sets where run = 2)
           order by number limit 1")
expect "facet show computes an unstored Pareto option ($other)" 0 \
    "$FACET" show "$WORK/f.db" --run 2 --option "$other"
same "... and stores its panel set" \
    "$(q "select count(*) from panel_sets where run = 2")" "$((budget + 1))"
same "... with as many panels as its option row has (SQLite)" \
    "$(q "select count(*) from panels where run = 2 and option = $other")" \
    "$(q "select panels from options where run = 2 and number = $other")"
