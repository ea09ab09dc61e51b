#!/usr/bin/env bash
# End-to-end: one rule for symbolic links and one limit on a project's
# files (issue 28, item 12). Facet reads through links and never writes
# through or over one: every writer (example, export, optimize's database,
# merge's output) refuses a link and leaves it and the file it points to
# as they were. A project is read from at most 256 files, and info,
# optimize and slurm say so in the same words. The real binary; what is on
# the disk is checked with stat, sha256sum and sqlite3.
# layers: cli core study store
. "$(dirname "$0")/lib.sh"

cd "$WORK" || exit 1
"$FACET" example plane --res 6 -o p.obj || exit 1
"$FACET" optimize p.obj --db real.db --u 2:3 --v 2:3 >/dev/null 2>&1 || exit 1
"$FACET" optimize p.obj --db shard.db --u 2:4 --v 2:4 >/dev/null 2>&1 || exit 1

# state LINK: the link's target, and the target's type and hash ("none"
# when absent), so that a check sees any write through or over the link.
state() {
    local to
    to=$(readlink "$1")
    printf '%s|%s|%s' "$(stat -c %F "$1" 2>/dev/null)" "$to" \
        "$(sha256sum "$to" 2>/dev/null | cut -c1-64 || echo none)"
}

# example -o LINK --force
echo "v 0 0 0" > target.obj
ln -s "$WORK/target.obj" link.obj
before=$(state link.obj)
expect_error "example -o a link --force is refused" \
    'link.obj is a symbolic link \(to .*target.obj\): Facet does not write through or over one' \
    "$FACET" example plane --res 4 -o link.obj --force
same "example: the link and its file are as they were" "$(state link.obj)" "$before"
ln -s "$WORK/nowhere.obj" dangling.obj
expect_error "example -o a dangling link is refused" 'dangling.obj is a symbolic link' \
    "$FACET" example plane --res 4 -o dangling.obj
if [ -e nowhere.obj ]; then fail "example: nothing made through a dangling link"; else pass "example: nothing made through a dangling link"; fi

# export --csv LINK --force
ln -s "$WORK/target.obj" link.csv
before=$(state link.csv)
expect_error "export --csv a link --force is refused" 'link.csv is a symbolic link' \
    "$FACET" export real.db --run 1 --option 1 --csv link.csv --force
same "export: the link and its file are as they were" "$(state link.csv)" "$before"

# optimize --db LINK: SQLite would write into the file behind it.
cp real.db behind.db
ln -s "$WORK/behind.db" link.db
before=$(state link.db)
expect_error "optimize --db a link is refused" 'link.db is a symbolic link \(to .*behind.db\)' \
    "$FACET" optimize p.obj --db link.db --u 2:3 --v 2:3
same "optimize: the database behind the link is unchanged" "$(state link.db)" "$before"
same "optimize: the database behind the link holds one run" \
    "$(sqlite3 behind.db 'SELECT count(*) FROM runs')" "1"
ln -s "$WORK/new.db" newlink.db
expect_error "optimize --db a dangling link is refused" 'newlink.db is a symbolic link' \
    "$FACET" optimize p.obj --db newlink.db --u 2:3 --v 2:3
if [ -e new.db ]; then fail "optimize: no database made through a dangling link"; else pass "optimize: no database made through a dangling link"; fi

# merge SHARD... into OUT, a link: the rename would put a file in its place.
"$FACET" optimize p.obj --db s1.db --u 2:5 --v 2:5 --shard 1/2 >/dev/null 2>&1 || exit 1
"$FACET" optimize p.obj --db s2.db --u 2:5 --v 2:5 --shard 2/2 >/dev/null 2>&1 || exit 1
cp real.db out-behind.db
ln -s "$WORK/out-behind.db" out.db
before=$(state out.db)
expect_error "merge into a link is refused" 'out.db is a symbolic link \(to .*out-behind.db\)' \
    "$FACET" merge out.db s1.db s2.db
same "merge: the link is still a link, its file unchanged" "$(state out.db)" "$before"
expect "merge into the file itself works" 0 "$FACET" merge out-behind.db s1.db s2.db
same "merge: the merged run is in the file" \
    "$(sqlite3 out-behind.db 'SELECT count(*) FROM runs')" "2"

# Reading goes through links: a surface, a database, a shard.
ln -s "$WORK/p.obj" plink.obj
expect "optimize reads a surface through a link" 0 \
    "$FACET" optimize plink.obj --db fromlink.db --u 2:3 --v 2:3
ln -s "$WORK/real.db" readlink.db
expect "runs reads a database through a link" 0 "$FACET" runs readlink.db
stdout_has "runs through a link lists the run" 'plane|p\.obj'
ln -s "$WORK/s1.db" s1link.db
expect "merge reads a shard through a link" 0 "$FACET" merge m.db s1link.db s2.db

# One limit on a project's files, said the same way by every command.
mkdir many
for i in $(seq 1 257); do
    printf 'o s%d\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n' "$i" > "many/s$i.obj"
done
files257=$(for i in $(seq 1 257); do printf 'many/s%d.obj ' "$i"; done)
files256=$(for i in $(seq 1 256); do printf 'many/s%d.obj ' "$i"; done)
limit='257 surface files: a project is read from at most 256 \(name its surfaces as objects in fewer OBJ files\)'
# shellcheck disable=SC2086
expect_error "info: 257 files, the project limit said" "$limit" "$FACET" info $files257
# shellcheck disable=SC2086
expect_error "optimize: 257 files, the same words" "$limit" \
    "$FACET" optimize $files257 --db many.db --module 1:2x1:2
if [ -e many.db ]; then fail "optimize: no database made for 257 files"; else pass "optimize: no database made for 257 files"; fi
# shellcheck disable=SC2086
expect_error "slurm: 257 files, the same words" "$limit" \
    "$FACET" slurm $files257 --shards 2 --results "$WORK/res" -o "$WORK/scripts"
# shellcheck disable=SC2086
run "$FACET" info $files256
if grep -q 'at most 256' "$ERR"; then fail "info: 256 files are within the limit"; else pass "info: 256 files are within the limit"; fi
