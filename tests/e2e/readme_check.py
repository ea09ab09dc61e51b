#!/usr/bin/env python3
"""readme_check.py ROOT WORK: the checks of tests/e2e/readme.sh.

Reads ROOT/README.md and ROOT/docs/manual.md, works in WORK, runs `facet`
from the PATH, and prints one "ok - " or "not ok - " line per check.

1. The walk-through: every `facet ...` line of the README's code blocks
   (continued lines joined) runs as written, in order, in WORK/walk, and
   exits 0. `facet tui` runs in tmux (a private server), where q must ask
   the question the README quotes and y must end it with status 0.
2. The demo's store: WORK/two holds the walk-through's demo.db with a
   second run added, as make demo's has (a small space stands in for the
   demo's 2,401 options, to keep this fast: what matters is that run 1 is
   no longer the only one). Every README command that reads demo.db runs
   there too and exits 0; one that names --run 1 prints what it printed
   in the walk-through.
3. The numbers the README quotes, against the truth: the knee, its grid
   and cost (sqlite3 over the store), the roof's area (the triangles of
   the OBJ, summed here), the options of the paper's space (counted in the
   store, and the product of the ranges), the rows of optimize's table
   (its own closing line); and docs/manual.md's count and list of the
   workbench's extra columns (the column chooser, on the screen).
4. The building of step 8: its seams in the store are the tower's own
   (rows x columns of faces read off the OBJ's object names), and show
   and the seams schedule give them.
"""

import csv
import os
import re
import shlex
import sqlite3
import subprocess
import sys
import time

ROOT, WORK = sys.argv[1], sys.argv[2]
README = open(os.path.join(ROOT, "README.md"), encoding="utf-8").read()
MANUAL = open(os.path.join(ROOT, "docs", "manual.md"), encoding="utf-8").read()
FAILED = False


def ok(name):
    print("ok - " + name)


def not_ok(name, *details):
    global FAILED
    FAILED = True
    print("not ok - " + name)
    for d in details:
        for line in str(d).splitlines()[:15]:
            print("  " + line)


def check(name, cond, *details):
    if cond:
        ok(name)
    else:
        not_ok(name, *details)


def flat(text):
    return " ".join(text.split())


def commands_of(text):
    """Every `facet` command line of text's fenced code blocks, continued
    lines (a trailing backslash) joined."""
    found, in_block, pending = [], False, ""
    for line in text.split("\n"):
        s = line.strip()
        if s.startswith("```"):
            in_block, pending = not in_block, ""
            continue
        if not in_block:
            continue
        s = (pending + " " + s).strip() if pending else s
        if s.endswith("\\"):
            pending = s[:-1].rstrip()
            continue
        pending = ""
        if re.match(r"(\./)?facet\s", s):
            found.append(s)
    return found


def short(cmd):
    return cmd if len(cmd) <= 90 else cmd[:87] + "..."


def run(cmd, cwd):
    started = time.monotonic()
    try:
        p = subprocess.run(["bash", "-c", cmd], cwd=cwd,
                           stdin=subprocess.DEVNULL, capture_output=True,
                           text=True, errors="replace", timeout=900)
        return p.returncode, p.stdout, p.stderr, time.monotonic() - started
    except subprocess.TimeoutExpired:
        return 124, "", "timed out", time.monotonic() - started


class Tmux:
    """facet tui in a tmux server of its own."""

    def __init__(self, name):
        self.cmd = ["tmux", "-L", "facet_readme_%d_%s" % (os.getpid(), name),
                    "-f", "/dev/null"]

    def start(self, command, cwd, width=100, height=45):
        self.exit_file = os.path.join(cwd, ".tui-exit")
        if os.path.exists(self.exit_file):
            os.remove(self.exit_file)
        shell = ("cd %s && PATH=%s TERM=xterm-256color %s 2>.tui-err; "
                 "echo $? > .tui-exit; sleep 600" %
                 (shlex.quote(cwd), shlex.quote(os.environ["PATH"]), command))
        subprocess.run(self.cmd + ["new-session", "-d", "-x", str(width),
                                   "-y", str(height), shell], check=True)

    def screen(self):
        return subprocess.run(self.cmd + ["capture-pane", "-p"],
                              capture_output=True, text=True,
                              errors="replace").stdout

    def keys(self, *keys):
        subprocess.run(self.cmd + ["send-keys"] + list(keys))

    def wait_for(self, pattern, seconds=30):
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            m = re.search(pattern, self.screen())
            if m:
                return m
            time.sleep(0.05)
        return None

    def exit_status(self, seconds=10):
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            if os.path.exists(self.exit_file):
                text = open(self.exit_file).read().strip()
                if text:
                    return int(text)
            time.sleep(0.05)
        return None

    def end(self):
        subprocess.run(self.cmd + ["kill-server"], capture_output=True)


def run_tui(cmd, cwd, where):
    """Runs a README `facet tui` line in tmux: it must show a run, ask the
    README's question on q, and end with status 0 on y."""
    m = re.search(r"asks `([^`]+)`", flat(README))
    question = m.group(1) if m else "Quit Facet? (y/n)"
    tmux = Tmux(where)
    try:
        tmux.start(cmd, cwd)
        shown = tmux.wait_for(r"paper space")
        check("README, %s: `%s` shows the run" % (where, short(cmd)), shown,
              tmux.screen())
        tmux.keys("q")
        asked = tmux.wait_for(re.escape(question), 10)
        check("README, %s: q on the first screen asks `%s`" %
              (where, question), asked, tmux.screen())
        tmux.keys("y")
        status = tmux.exit_status(5)
        if status is None:   # a (y/n) that still waits for Enter
            tmux.keys("Enter")
            status = tmux.exit_status(10)
        check("README, %s: `%s` exits 0 after y" % (where, short(cmd)),
              status == 0, "status %s" % status, tmux.screen())
    finally:
        tmux.end()


def run_all(commands, cwd, where):
    """Runs commands in cwd; returns {command: stdout}."""
    outputs = {}
    for cmd in commands:
        if re.match(r"(\./)?facet\s+tui\b", cmd):
            run_tui(cmd, cwd, where)
            continue
        status, out, err, seconds = run(cmd, cwd)
        outputs[cmd] = out
        check("README, %s: `%s` exits 0 (%.1f s)" % (where, short(cmd),
                                                     seconds),
              status == 0, "status %d" % status, err[-2000:])
    return outputs


def obj_area(path):
    """The area of an OBJ's faces (fans of triangles), from its own
    numbers."""
    vs, area = [], 0.0
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vs.append(tuple(float(x) for x in line.split()[1:4]))
            elif line.startswith("f "):
                idx = [int(w.split("/")[0]) for w in line.split()[1:]]
                p = [vs[i - 1 if i > 0 else len(vs) + i] for i in idx]
                for k in range(1, len(p) - 1):
                    a = [p[k][j] - p[0][j] for j in range(3)]
                    b = [p[k + 1][j] - p[0][j] for j in range(3)]
                    c = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                         a[0] * b[1] - a[1] * b[0])
                    area += 0.5 * (c[0] ** 2 + c[1] ** 2 + c[2] ** 2) ** 0.5
    return area


def check_numbers(walk, outputs, commands):
    text = flat(README)
    db = sqlite3.connect(os.path.join(walk, "demo.db"))
    knee = db.execute("SELECT number, nu, nv, cost FROM options "
                      "WHERE run = 1 AND knee").fetchall()
    m = re.search(r"Option (\d+) is the knee of this run \((\d+) x (\d+) "
                  r"panels, ([\d,]+) USD\)", text)
    if not m or len(knee) != 1:
        not_ok("README names the knee of run 1, and the store has one",
               "README: %s" % (m and m.group(0)), "store: %s" % knee)
    else:
        number, nu, nv, cost = knee[0]
        said = (int(m.group(1)), int(m.group(2)), int(m.group(3)),
                m.group(4))
        truth = (number, nu, nv, "{:,}".format(round(cost)))
        check("README's knee, %s x %s panels, %s USD: option %s (sqlite3: "
              "option %s, %s x %s, %s USD)" % (said[1], said[2], said[3],
                                               said[0], *truth),
              said == truth)
        # the demo's store's; the building of step 8 has its own
        named = sorted({int(x) for c in commands if "demo.db" in c
                        for x in re.findall(r"--option (\d+)", c)})
        check("every --option of the README's commands is the knee (%s)" %
              named, named == [number])

    area = obj_area(os.path.join(walk, "roof.obj"))
    m = re.search(r"the area \((\d[\d,]*\.\d+) m\^2\)", text)
    check("README's area of the roof, %s m^2, is its triangles' (%.3f)" %
          (m and m.group(1), area),
          m and abs(float(m.group(1).replace(",", "")) - area) < 0.0005)
    m = re.search(r"of about ([\d,]+) m\^2", text)
    check("README's roof of about %s m^2 is within 1%% of %.1f" %
          (m and m.group(1), area),
          m and abs(float(m.group(1).replace(",", "")) - area) < 0.01 * area)

    m = re.search(r"\(U (\d+) to (\d+) panels, V (\d+) to (\d+), (\d+) mm; "
                  r"(\d+) options\)", text)
    stored = db.execute("SELECT count(*) FROM options WHERE run = 1"
                        ).fetchone()[0]
    optimize = [c for c in commands if re.match(r"facet optimize ", c) and
                "demo.db" in c]
    if not m or len(optimize) != 1:
        not_ok("README's paper space and its one optimize command",
               m and m.group(0), optimize)
    else:
        u1, u2, v1, v2, t, n = (int(x) for x in m.groups())
        check("README's space, U %d:%d, V %d:%d, %d mm, is its command's" %
              (u1, u2, v1, v2, t),
              re.search(r"--u %d:%d --v %d:%d\s+--threshold %d\b" %
                        (u1, u2, v1, v2, t), optimize[0]), optimize[0])
        check("README's %d options: %d in the store, %d grids in the "
              "space" % (n, stored, (u2 - u1 + 1) * (v2 - v1 + 1)),
              n == stored == (u2 - u1 + 1) * (v2 - v1 + 1))
        m = re.search(r"its table of (\d+) options", text)
        shown = re.search(r"^\((\d+) of (\d+) options", outputs.get(
            optimize[0], ""), re.M)
        check("README's table of %s options is optimize's (%s)" %
              (m and m.group(1), shown and shown.group(0)),
              m and shown and int(m.group(1)) == int(shown.group(1)) and
              int(shown.group(2)) == stored)


def check_seams(walk, outputs, commands):
    """The building of step 8: its seams, counted in the store, are the
    tower's own (its faces, named skin_rRR_cCC in the OBJ, a ring of
    columns in rows: each meets its neighbour in its row, the ring closed,
    and the face above it), and show and the seams schedule say so."""
    obj = os.path.join(walk, "skin.obj")
    db_path = os.path.join(walk, "skin.db")
    if not (os.path.exists(obj) and os.path.exists(db_path)):
        not_ok("the walk-through made skin.obj and skin.db")
        return
    faces = set()
    for line in open(obj, encoding="utf-8"):
        m = re.match(r"o skin_r(\d+)_c(\d+)\s*$", line)
        if m:
            faces.add((int(m.group(1)), int(m.group(2))))
    rows = len({r for r, _ in faces})
    cols = len({c for _, c in faces})
    truth = rows * cols + (rows - 1) * cols
    db = sqlite3.connect(db_path)
    stored = db.execute("SELECT seams FROM options WHERE run = 1 "
                        "AND number = 1").fetchone()
    check("README's building: %d rows of %d faces (the OBJ), %d seams "
          "(sqlite3: %s)" % (rows, cols, truth, stored),
          len(faces) == rows * cols == 180 and stored == (truth,))
    check("README quotes the building's %d seams, 180 in rows, 160 between"
          % truth, truth == 340 and "along 340 seams: 180 between "
          "neighbours in a row, 160 between rows" in flat(README))
    show = [c for c in commands if c.startswith("facet show skin.db")]
    check("README's show of the building prints its seams line",
          show and re.search(r"^seams +%d, " % truth,
                             outputs.get(show[0], ""), re.M),
          show and outputs.get(show[0], "")[:800])
    seams_csv = os.path.join(walk, "skin-seams.csv")
    if not os.path.exists(seams_csv):
        not_ok("export --csv of the building wrote skin-seams.csv")
        return
    with open(seams_csv, encoding="utf-8") as f:
        seam_rows = list(csv.DictReader(f))
    check("skin-seams.csv: one row per seam joint, of the %d seams" % truth,
          len({r["seam"] for r in seam_rows}) == truth,
          "%d seams in the file" % len({r["seam"] for r in seam_rows}))


def check_columns(two):
    """docs/manual.md's count and list of the columns the chooser adds,
    against the chooser on the screen."""
    m = re.search(r"\((\d+) more can be shown: (.*?)\)\s*;", flat(MANUAL))
    if not m:
        not_ok("docs/manual.md says how many more columns can be shown")
        return
    said, listed = int(m.group(1)), re.findall(r"`([a-z_]+)`", m.group(2))
    db = sqlite3.connect(os.path.join(two, "demo.db"))
    names = {r[0] for r in db.execute(
        "SELECT name FROM pragma_table_info('options')")}
    tmux = Tmux("columns")
    try:
        tmux.start("facet tui demo.db", two)
        tmux.wait_for(r"paper space")
        tmux.keys("Enter")
        tmux.wait_for(r"row \d")
        tmux.keys("C")
        counts = tmux.wait_for(r"Columns: (\d+) of (\d+) shown")
        screen = tmux.screen()
    finally:
        tmux.end()
    if not counts:
        not_ok("the column chooser opens", screen)
        return
    hidden = []
    for line in screen.splitlines():
        row = re.search(r"\[ \]\s+(.*)", line)
        if row:
            known = [w for w in row.group(1).split() if w in names]
            if known:
                hidden.append(known[-1])
    more = int(counts.group(2)) - int(counts.group(1))
    check("docs/manual.md: %d more columns can be shown; the chooser: %s, "
          "%d more" % (said, counts.group(0), more), said == more)
    check("docs/manual.md lists the %d the chooser hides" % len(hidden),
          listed == hidden, "manual:  %s" % " ".join(listed),
          "chooser: %s" % " ".join(hidden))


def main():
    commands = commands_of(README)
    check("the README has its walk-through's commands (%d)" % len(commands),
          len(commands) >= 10)
    walk = os.path.join(WORK, "walk")
    os.makedirs(walk)
    outputs = run_all(commands, walk, "walk-through")
    if not os.path.exists(os.path.join(walk, "demo.db")):
        not_ok("the walk-through made demo.db")
        return
    check_numbers(walk, outputs, commands)
    check_seams(walk, outputs, commands)

    two = os.path.join(WORK, "two")
    os.makedirs(two)
    with open(os.path.join(walk, "demo.db"), "rb") as f, \
            open(os.path.join(two, "demo.db"), "wb") as g:
        g.write(f.read())
    status, _, err, _ = run(
        "facet optimize %s --db demo.db --u 12:20 --v 16:20 --threshold 3 "
        "--sp-as-fp --max-panel-area 1.92 --panel-cost 150 --joint-cost 60 "
        "--mould-cost 1500,6000 --objectives cost,moulds "
        "--name 'illustrative costs'" %
        shlex.quote(os.path.join(walk, "roof.obj")), two)
    check("a second run goes into the demo's store", status == 0, err)
    reading = [c for c in commands if re.search(r"\bdemo\.db\b", c) and
               not re.match(r"facet optimize ", c)]
    again = run_all(reading, two, "a store of two runs")
    for cmd in reading:
        if re.search(r"--run 1\b", cmd) and cmd in again:
            check("README, a store of two runs: `%s` prints what it did "
                  "with one" % short(cmd), again[cmd] == outputs.get(cmd),
                  again[cmd][:800])
    check_columns(two)


main()
sys.exit(0)
