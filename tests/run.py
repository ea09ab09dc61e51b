#!/usr/bin/env python3
"""Runs the test suites of one or more builds, side by side.

    tests/run.py [--jobs N] [--changed] [--fail-fast] [--only NAME ...] BUILD...

A suite is a cmocka unit test (BUILD/tests/test_*) or an end-to-end script
(tests/e2e/*.sh, which runs BUILD/facet). Every suite of every BUILD named
goes into one queue, longest first, and N of them (default: the machine's
cores) run at a time. Each suite's output goes to a log of its own, printed
whole when the suite fails; a line per suite gives its counts and its wall
time, and the end gives the slowest twenty suites and the totals.

Counting is the one tests/e2e/lib.sh and cmocka define: "ok - ",
"not ok - " and "skip - " lines of a script; cmocka's PASSED, FAILED and
SKIPPED summaries. A suite that exits non-zero with no failure counted is
one failure; a skip is counted apart, never as passed. The run fails when
anything failed or nothing passed.

Fixtures (the surfaces and databases several scripts start from, see
tests/e2e/fixtures.sh) are made once per run, into a fresh folder named by
FACET_FIXTURES, by the first build's facet, and shared by every suite of
every build (with --only or --changed, when a suite first asks for one).

--changed keeps the unit tests and the end-to-end scripts whose "# layers:"
line names a layer (core, store, study, tui, cli) that the working tree
changes against HEAD (or, on a clean tree, that HEAD changed), plus any
script changed itself; a change to the test harness keeps every script.
This is make check-fast, the edit-test loop; make check runs everything.

Suites that share a machine-wide resource say so with a "# lock: NAME" line
(the single-node Slurm cluster); two suites of one lock never run at once.

"Longest first" uses the wall time each suite took in this build's last
run (BUILD/suite-times.tsv, written at the end of every run), else the
times of a quiet run kept in tests/suite-times.tsv (a fresh clone: CI).
The order changes how long a run takes, never what it checks.

--fail-fast starts no suite once one has failed; --first-failure also
stops every running suite at the first failing check (tests/mutants.sh).
A suite still running after SUITE_TIMEOUT seconds is stopped and failed.
"""

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
E2E = os.path.join(ROOT, "tests", "e2e")
LAYERS = ("core", "store", "study", "tui", "cli")
# A suite that runs this long is stopped and failed: a hang is a defect,
# and the run must end.
SUITE_TIMEOUT = 1200
TIMES_FILE = "suite-times.tsv"


class Suite:
    def __init__(self, build, kind, name, path):
        self.build = build
        self.kind = kind          # "unit" or "e2e"
        self.name = name          # test_obj, e2e/optimize
        self.path = path
        self.layers = set()
        self.lock = None
        self.estimate = 0.0
        self.passed = self.failed = self.skipped = 0
        self.seconds = 0.0
        self.cpu = None           # user + system seconds, itself and all
                                  # it waited for; None when it was killed
        self.log = None
        self.skips = []
        self.stopped = False      # stopped by --first-failure
        if kind == "e2e":
            self.read_header()

    def key(self):
        return self.build + "\t" + self.name

    def read_header(self):
        with open(self.path, encoding="utf-8") as f:
            for line in f:
                if not line.startswith("#"):
                    if line.strip():
                        break
                    continue
                m = re.match(r"#\s*layers:\s*(.*)$", line)
                if m:
                    self.layers = set(m.group(1).split())
                m = re.match(r"#\s*lock:\s*(\S+)", line)
                if m:
                    self.lock = m.group(1)


def find_suites(builds, only):
    suites = []
    scripts = sorted(
        f for f in os.listdir(E2E)
        if f.endswith(".sh") and not f.endswith("lib.sh") and f != "fixtures.sh")
    for build in builds:
        tests = os.path.join(ROOT, build, "tests")
        if os.path.isdir(tests):
            for f in sorted(os.listdir(tests)):
                path = os.path.join(tests, f)
                if f.startswith("test_") and os.access(path, os.X_OK) and \
                        not f.endswith(".d"):
                    suites.append(Suite(build, "unit", f, path))
        for f in scripts:
            suites.append(Suite(build, "e2e", "e2e/" + f[:-3],
                                os.path.join(E2E, f)))
    if only:
        # A script's file name (optimize.sh) names its suite too.
        wanted = {w[:-3] if w.endswith(".sh") else w for w in only}
        suites = [s for s in suites
                  if s.name in wanted or s.name.replace("e2e/", "") in wanted]
    return suites


def changed_files():
    def git(*args):
        r = subprocess.run(("git",) + args, cwd=ROOT, capture_output=True,
                           text=True)
        if r.returncode != 0:
            return None
        return [line for line in r.stdout.splitlines() if line]
    files = git("diff", "--name-only", "HEAD")
    if files is None:
        return None
    files += git("ls-files", "--others", "--exclude-standard") or []
    if not files:
        files = git("diff", "--name-only", "HEAD~1", "HEAD") or []
    return files


def keep_changed(suites, files=None):
    if files is None:
        files = changed_files()
    if files is None:
        print("run.py: not a git checkout; --changed keeps every suite")
        return suites
    layers = set()
    scripts = set()
    everything = False
    for f in files:
        top = f.split("/")[0]
        if top in LAYERS:
            layers.add(top)
        elif f.startswith("tests/e2e/"):
            base = os.path.basename(f)
            if base.endswith(".sh") and not base.endswith("lib.sh") and \
                    base != "fixtures.sh":
                scripts.add("e2e/" + base[:-3])
            else:
                everything = True
        elif f in ("Makefile", "tests/run.py"):
            everything = True
    print("run.py: changed layers: %s%s" % (
        " ".join(sorted(layers)) or "none",
        "; the harness changed, so every script" if everything else ""))
    return [s for s in suites
            if s.kind == "unit" or everything or s.name in scripts or
            (s.layers & layers)]


def read_times_file(path, build, times):
    """Adds the times of path (lines: variant, suite, seconds) for build."""
    variant = os.path.basename(build)
    try:
        with open(path, encoding="utf-8") as f:
            for line in f:
                parts = line.rstrip("\n").split("\t")
                if len(parts) == 3 and parts[0] in (variant, "release"):
                    key = build + "\t" + parts[1]
                    # A variant's own time over the release's.
                    if parts[0] == variant or key not in times:
                        times[key] = float(parts[2])
    except (OSError, ValueError):
        pass


def read_times(builds):
    """The wall time each suite took last, to start the longest first: this
    build's last run (BUILD/suite-times.tsv), else tests/suite-times.tsv, a
    quiet run's times kept with the sources for a fresh clone (CI); a
    variant with no times of its own (clang) takes the release's."""
    times = {}
    for build in builds:
        read_times_file(os.path.join(ROOT, "tests", TIMES_FILE), build, times)
        read_times_file(os.path.join(ROOT, build, TIMES_FILE), build, times)
    return times


def write_times(suites):
    by_build = {}
    for s in suites:
        by_build.setdefault(s.build, []).append(s)
    for build, group in by_build.items():
        path = os.path.join(ROOT, build, TIMES_FILE)
        variant = os.path.basename(build)
        old = {}
        read_times_file(path, build, old)
        for s in group:
            old[s.key()] = s.seconds
        tmp = path + ".tmp"
        try:
            with open(tmp, "w", encoding="utf-8") as f:
                for k in sorted(old):
                    f.write("%s\t%s\t%.1f\n" % (variant, k.split("\t")[1],
                                                 old[k]))
            os.replace(tmp, path)
        except OSError as e:
            print("run.py: cannot keep the suites' times in %s: %s" % (path, e))


def default_estimate(s):
    # With no earlier run's times: scripts before unit tests, a sanitizer
    # build's before the release's, the longer script first.
    weight = os.path.getsize(s.path) / 1000.0 if s.kind == "e2e" else 1.0
    if "san" in s.build:
        weight *= 3
    return weight


def count(suite, status, log_text):
    if suite.kind == "unit":
        ok = sum(int(n) for n in re.findall(r"\[  PASSED  \] (\d+)", log_text))
        bad = sum(int(n) for n in
                  re.findall(r"\[  FAILED  \] (\d+) test", log_text))
        skip = sum(int(n) for n in
                   re.findall(r"\[  SKIPPED \] (\d+) test", log_text))
        skips = [line for line in log_text.splitlines()
                 if line.startswith("skipped: ")]
    else:
        lines = log_text.splitlines()
        ok = sum(1 for line in lines if line.startswith("ok "))
        bad = sum(1 for line in lines if line.startswith("not ok "))
        skip = sum(1 for line in lines if line.startswith("skip "))
        skips = [line for line in lines if line.startswith("skip ")]
    if status != 0 and bad == 0:
        bad = 1
    suite.passed, suite.failed, suite.skipped = ok, bad, skip
    suite.skips = skips


FAILURE_MARK = re.compile(rb"^(not ok |\[  FAILED  \])", re.M)


def run_suite(suite, env, logs, stop=None, first_failure=False):
    """Runs one suite into its log. With stop (a threading.Event), the suite
    is stopped when stop is set; with first_failure, its first failing check
    sets stop (the mutants need a failure, not the whole suite)."""
    safe = suite.build.replace("/", "_") + "__" + suite.name.replace("/", "_")
    suite.log = os.path.join(logs, safe + ".log")
    suite_env = dict(env)
    suite_env["BUILD"] = suite.build
    suite_env["FACET"] = os.path.join(ROOT, suite.build, "facet")
    cmd = [suite.path] if suite.kind == "unit" else ["bash", suite.path]
    start = time.monotonic()
    with open(suite.log, "wb") as log:
        try:
            proc = subprocess.Popen(cmd, cwd=ROOT, env=suite_env, stdout=log,
                                    stderr=subprocess.STDOUT,
                                    stdin=subprocess.DEVNULL,
                                    start_new_session=True)
        except OSError as e:
            log.write(("cannot start %s: %s\n" % (suite.path, e)).encode())
            status = 127
        else:
            status = watch(proc, suite, log, start, stop, first_failure)
    suite.seconds = time.monotonic() - start
    with open(suite.log, encoding="utf-8", errors="replace") as f:
        count(suite, status, f.read())


def watch(proc, suite, log, start, stop, first_failure):
    """Waits for a suite's process; the exit status, or 124 for a suite
    that ran past SUITE_TIMEOUT (a hang), both failures."""
    while True:
        # wait4, not Popen.wait: its rusage holds the CPU of the suite and
        # of every process it waited for (facet, python, tmux clients), so
        # that a suite's wall time can be told from the work it does.
        pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
        if pid:
            proc.returncode = os.waitstatus_to_exitcode(status)
            suite.cpu = usage.ru_utime + usage.ru_stime
            return proc.returncode
        time.sleep(0.05)
        if first_failure:
            log.flush()
            with open(suite.log, "rb") as f:
                found = FAILURE_MARK.search(f.read())
            if found:
                # Its own failure: stopped before a summary could count it
                # (cmocka names a failing test long before its totals).
                stop.set()
                os.killpg(proc.pid, 9)
                proc.wait()
                log.write(b"not ok - stopped at its first failure\n")
                return 1
        if stop is not None and stop.is_set():
            os.killpg(proc.pid, 9)
            proc.wait()
            suite.stopped = True
            return 0
        if time.monotonic() - start > SUITE_TIMEOUT:
            os.killpg(proc.pid, 9)
            proc.wait()
            log.write(("not ok - %s: still running after %d s, stopped\n"
                       % (suite.name, SUITE_TIMEOUT)).encode())
            return 124


def label(suite, builds):
    if len(builds) == 1:
        return suite.name
    return "%s %s" % (os.path.basename(suite.build), suite.name)


def make_fixtures(env, builds):
    """Runs tests/e2e/fixtures.sh once with the first build's facet."""
    script = os.path.join(E2E, "fixtures.sh")
    if not os.path.exists(script):
        return True
    fixture_env = dict(env)
    fixture_env["BUILD"] = builds[0]
    fixture_env["FACET"] = os.path.join(ROOT, builds[0], "facet")
    start = time.monotonic()
    r = subprocess.run(["bash", script], cwd=ROOT, env=fixture_env,
                       capture_output=True, text=True)
    print("%-40s %s in %.1f s" % ("fixtures (%s/facet)" % builds[0],
                                   "made" if r.returncode == 0 else "FAILED",
                                   time.monotonic() - start), flush=True)
    if r.returncode != 0:
        sys.stdout.write(r.stdout + r.stderr)
    return r.returncode == 0


def main():
    ap = argparse.ArgumentParser(description="Runs the test suites.")
    ap.add_argument("builds", nargs="+", metavar="BUILD")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--changed", action="store_true")
    ap.add_argument("--changed-files", nargs="+", metavar="FILE",
                    help="as --changed, for these files (tests/mutants.sh)")
    ap.add_argument("--fail-fast", action="store_true",
                    help="start no suite after one has failed")
    ap.add_argument("--first-failure", action="store_true",
                    help="stop every suite at the first failing check")
    ap.add_argument("--shortest-first", action="store_true",
                    help="the shortest suites first: a first failure "
                    "sooner (tests/mutants.sh)")
    ap.add_argument("--only", nargs="*", default=[])
    ap.add_argument("--quiet", action="store_true",
                    help="no line per suite that passed")
    args = ap.parse_args()
    builds = [b.rstrip("/") for b in args.builds]
    for b in builds:
        if not os.access(os.path.join(ROOT, b, "facet"), os.X_OK):
            print("run.py: %s/facet is not built" % b)
            return 2

    suites = find_suites(builds, args.only)
    if args.changed_files:
        suites = keep_changed(suites, args.changed_files)
    elif args.changed:
        suites = keep_changed(suites)
    times = read_times(builds)
    for s in suites:
        s.estimate = times.get(s.key(), default_estimate(s))
    queue = sorted(suites, key=lambda s: s.estimate if args.shortest_first
                   else -s.estimate)

    env = dict(os.environ)
    env.setdefault("FACET_DATA", os.path.join(os.path.dirname(ROOT),
                                              "shared", "data"))
    env.setdefault("ASAN_OPTIONS", "detect_leaks=1:abort_on_error=0")
    env.setdefault("UBSAN_OPTIONS", "print_stacktrace=1:halt_on_error=1")
    logs = tempfile.mkdtemp(prefix="facet-tests.")
    fixtures = os.path.join(logs, "fixtures")
    os.mkdir(fixtures)
    env["FACET_FIXTURES"] = fixtures
    started = time.monotonic()
    try:
        # A run of some suites only makes each fixture when a suite first
        # asks for it (lib.sh), with that suite's build.
        if not (args.only or args.changed or args.changed_files) and \
                not make_fixtures(env, builds):
            # The suites that need the missing fixtures fail on their own,
            # each naming it; the others still run.
            print("run.py: some fixtures could not be made; see above")
        done = run_queue(queue, env, logs, args, builds)
        return report(done, queue, builds, started, args)
    finally:
        shutil.rmtree(logs, ignore_errors=True)


def run_queue(queue, env, logs, args, builds):
    lock = threading.Condition()
    held = set()
    done = []
    failed = [False]
    stop = threading.Event()

    def take():
        with lock:
            while True:
                if not queue or stop.is_set() or \
                        (args.fail_fast and failed[0]):
                    return None
                for i, s in enumerate(queue):
                    if s.lock is None or s.lock not in held:
                        queue.pop(i)
                        if s.lock:
                            held.add(s.lock)
                        return s
                lock.wait()

    def worker():
        while True:
            s = take()
            if s is None:
                return
            run_suite(s, env, logs, stop, args.first_failure)
            with lock:
                if s.lock:
                    held.discard(s.lock)
                done.append(s)
                if s.failed:
                    failed[0] = True
                if s.stopped and not s.failed:
                    print("%-36s stopped (another suite failed) %7.1f s" %
                          (label(s, builds), s.seconds), flush=True)
                elif not (args.quiet and s.failed == 0):
                    print("%-36s %4d passed %3d failed %3d skipped %7.1f s"
                          "%s" % (label(s, builds), s.passed, s.failed,
                                  s.skipped, s.seconds, cpu_text(s)),
                          flush=True)
                if s.failed:
                    print_log(s, builds)
                lock.notify_all()

    threads = [threading.Thread(target=worker) for _ in range(max(1, args.jobs))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return done


def cpu_text(suite):
    """The suite's CPU time, said beside its wall time: a suite whose CPU is
    far below its wall time waits (sleeps, timeouts), one near it works."""
    if suite.cpu is None:
        return "  cpu     -  "
    return "  cpu %7.1f s" % suite.cpu


def print_log(s, builds):
    print("==== %s: the whole log" % label(s, builds))
    with open(s.log, encoding="utf-8", errors="replace") as f:
        sys.stdout.write(f.read())
    print("==== end of %s" % label(s, builds), flush=True)


def report(done, left, builds, started, args):
    wall = time.monotonic() - started
    if done:
        write_times(done)
    print("\nslowest suites (wall time, CPU):")
    for s in sorted(done, key=lambda s: -s.seconds)[:20]:
        print("  %7.1f s %s  %s" % (s.seconds, cpu_text(s),
                                    label(s, builds)))
    for s in done:
        for line in s.skips:
            print("SKIPPED %s: %s" % (label(s, builds), line))
    if left:
        print("NOT RUN (after a failure): %d suites" % len(left))
    failed_names = [label(s, builds) for s in done if s.failed]
    if failed_names:
        print("FAILED: " + ", ".join(failed_names))
    total_p = total_f = total_s = 0
    for b in builds:
        group = [s for s in done if s.build == b]
        p = sum(s.passed for s in group)
        f = sum(s.failed for s in group)
        k = sum(s.skipped for s in group)
        total_p, total_f, total_s = total_p + p, total_f + f, total_s + k
        print("%s: %d passed, %d failed, %d skipped "
              "(not run here, not counted as passed)" % (b, p, f, k))
    cpu = sum(s.cpu for s in done if s.cpu is not None)
    print("%d suites in %.0f s wall on %d jobs, %.0f s CPU" %
          (len(done), wall, args.jobs, cpu))
    return 0 if total_f == 0 and total_p > 0 and not left else 1


if __name__ == "__main__":
    sys.exit(main())
