# shard_lib.sh: comparing a merged run with the unsharded one, by SQLite
# itself, for shard.sh and slurm.sh (after lib.sh).

# cols DB: the columns of options but run, comma-separated.
cols() {
    sqlite3 -batch "$1" "SELECT group_concat(name, ',') FROM
        (SELECT name FROM pragma_table_info('options') WHERE name <> 'run'
         ORDER BY cid)"
}

# same_options NAME A B: the options of A's and B's only runs are equal in
# every column but the run id (SQLite compares the values exactly), and
# so are the runs' front, hypervolume, knee and best cost.
same_options() {
    local c diff runs
    c=$(cols "$2")
    diff=$(sqlite3 -batch "$2" "ATTACH '$3' AS b;
        SELECT ((SELECT count(*) FROM (SELECT $c FROM main.options
                                       EXCEPT SELECT $c FROM b.options))
              + (SELECT count(*) FROM (SELECT $c FROM b.options
                                       EXCEPT SELECT $c FROM main.options)))
             || ' ' || (SELECT count(*) FROM main.options)
             || ' ' || (SELECT count(*) FROM b.options)")
    runs=$(sqlite3 -batch "$2" "ATTACH '$3' AS b;
        SELECT count(*) FROM (SELECT pareto_options, hypervolume, knee,
                                     best_cost, options FROM main.runs
                              EXCEPT SELECT pareto_options, hypervolume,
                                     knee, best_cost, options FROM b.runs)")
    local n
    n=$(sqlite3 -batch "$2" "SELECT count(*) FROM options")
    same "$1" "$diff runs:$runs" "0 $n $n runs:0"
}

# same_rows NAME A B TABLE: every row of TABLE in A's file is in B's and
# back, over every column but the run id (SQLite compares the values
# exactly), and both hold the same number of rows.
same_rows() {
    local c diff n
    c=$(sqlite3 -batch "$2" "SELECT group_concat(name, ',') FROM
        (SELECT name FROM pragma_table_info('$4') WHERE name <> 'run'
         ORDER BY cid)")
    diff=$(sqlite3 -batch "$2" "ATTACH '$3' AS b;
        SELECT ((SELECT count(*) FROM (SELECT $c FROM main.$4
                                       EXCEPT SELECT $c FROM b.$4))
              + (SELECT count(*) FROM (SELECT $c FROM b.$4
                                       EXCEPT SELECT $c FROM main.$4)))
             || ' ' || (SELECT count(*) FROM main.$4)
             || ' ' || (SELECT count(*) FROM b.$4)")
    n=$(sqlite3 -batch "$2" "SELECT count(*) FROM $4")
    same "$1" "$diff" "0 $n $n"
}
