#!/usr/bin/env python3
"""Picks the GPU tests that run under the sanitizers, from per-test line coverage.

scripts/choose-sanitize-tests.sh runs every test of a coverage build alone and leaves, in DATA
(build/coverage/sanitize-choice/):
  results.tsv     one line a test: ctest number, name, label, seconds, status
  runs/N/...      the .gcda files test N wrote, under the build tree's full path (GCOV_PREFIX)
  gcno/...        the build's .gcno files, by their path in the build tree
  driver.txt      which lavapipe the tests ran on

This reads each run with gcov (cached in DATA/lines/N.txt as "host/...:line"), and then:
  target  the host/ lines that some test labelled gpu* runs and no test labelled host runs: the
          host code only a device reaches, which the sanitizers see only through GPU tests;
  cover   a greedy weighted set cover of the target by the GPU tests, taking each time the test
          that adds the most target lines per second (the cheap ones first, see TIERS);
and prints a summary, the chosen tests in order of what they add, and the CMake lists for
tests/CMakeLists.txt: rtvk_quick_tests, the first QUICK of them, and rtvk_unsanitized_gpu_tests,
the GPU tests left out (so that a GPU test added later is sanitized until measured).

Usage: choose_sanitize_tests.py [--build DIR] [--source DIR] DATA
Exits 1 when a test failed or was skipped (its lines count only as far as it ran, so the lists
may be short; a test stopped at the timeout is only reported: it is too slow to be chosen), 2 on
a bad argument.
"""
import argparse
import collections
import concurrent.futures
import json
import os
import subprocess
import sys
import tempfile

# The cheap tests are tried first: a test of up to 10 s is taken before any slower one for as long
# as the cheap ones still add lines; then up to 30 s. A test slower than that costs more under the
# sanitizers (several times slower) than its few lines are worth, and its lines are reported as
# missed instead.
TIERS = (10.0, 30.0)
# How many of the chosen tests, by what they add, `scripts/test.sh --quick` runs: about 93% of
# the target in about 40 s.
QUICK = 11
# A test's seconds are never taken as less than this: ctest rounds to hundredths, and a test
# that "takes no time" would otherwise win on any one line.
MIN_SECONDS = 0.05
# How many .gcda files one gcov call reads; its JSON for all of a run's files at once is large.
GCOV_BATCH = 40


class ArgumentParser(argparse.ArgumentParser):
    def error(self, message):  # one line, as the project's scripts say a bad argument
        print(f"rtvk: choose_sanitize_tests.py: {message}", file=sys.stderr)
        sys.exit(2)


def parse_args():
    here = os.path.dirname(os.path.abspath(__file__))
    p = ArgumentParser(description="Picks the sanitize GPU tests from per-test line coverage.")
    p.add_argument("data", help="the runs' folder (build/coverage/sanitize-choice)")
    p.add_argument("--build", help="the build tree the runs were made in (default: DATA/..)")
    p.add_argument("--source", default=os.path.dirname(here), help="the checkout (default: ..)")
    a = p.parse_args()
    a.data = os.path.realpath(a.data)
    a.build = os.path.realpath(a.build or os.path.dirname(a.data))
    a.source = os.path.realpath(a.source)
    if not os.path.isfile(os.path.join(a.data, "results.tsv")):
        p.error(f"'{a.data}' has no results.tsv (run scripts/choose-sanitize-tests.sh)")
    return a


def read_results(data):
    """The tests that ran: {name: dict(num, label, secs, status, gpu, gtest)}. Only GoogleTest's
    tests (gtest.txt, from rtvk_tests --gtest_list_tests) can be chosen: the lists are
    GoogleTest filters, which a script test (Install, Oracle, Readme) would never match."""
    gtest_file = os.path.join(data, "gtest.txt")
    gtests = None
    if os.path.exists(gtest_file):
        with open(gtest_file) as fh:
            gtests = {line.strip() for line in fh if line.strip()}
    tests = {}
    with open(os.path.join(data, "results.tsv")) as fh:
        for row in fh:
            num, name, label, secs, status = row.rstrip("\n").split("\t")
            tests[name] = dict(num=num, label=label, secs=float(secs), status=status,
                               gpu=label.startswith("gpu"),
                               gtest=gtests is None or name in gtests)
    return tests


def gcov_json(gcdas, cwd):
    """gcov's JSON for some .gcda files: one document per file, one after another on stdout."""
    r = subprocess.run(["gcov", "--json-format", "--stdout", *gcdas], cwd=cwd,
                       capture_output=True, text=True, check=False)
    dec, s, i, docs = json.JSONDecoder(), r.stdout, 0, []
    while True:
        while i < len(s) and s[i].isspace():
            i += 1
        if i >= len(s):
            return docs
        doc, i = dec.raw_decode(s, i)
        docs.append(doc)


def gcdas_of_run(data, build, num):
    """The run's .gcda files, each with the build's .gcno linked beside it, where gcov looks."""
    root = os.path.join(data, "runs", num, build.lstrip("/"))
    gcdas, missing = [], 0
    for d, _, files in os.walk(root):
        for f in files:
            if not f.endswith(".gcda"):
                continue
            gcda = os.path.join(d, f)
            gcno = os.path.join(data, "gcno", os.path.relpath(gcda, root))[:-5] + ".gcno"
            if not os.path.exists(gcno):
                missing += 1
                continue
            if not os.path.lexists(gcda[:-5] + ".gcno"):
                os.symlink(gcno, gcda[:-5] + ".gcno")
            gcdas.append(gcda)
    return gcdas, missing


def lines_of_run(data, build, source, num):
    """The host lines run N ran, as "host/dir/file.cpp:line"; read once, then from the cache."""
    cache = os.path.join(data, "lines", f"{num}.txt")
    if os.path.exists(cache):
        with open(cache) as fh:
            return num, set(fh.read().split()), 0
    gcdas, missing = gcdas_of_run(data, build, num)
    host = os.path.join(source, "host") + os.sep
    covered = set()
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(0, len(gcdas), GCOV_BATCH):
            for doc in gcov_json(gcdas[k:k + GCOV_BATCH], tmp):
                cwd = doc.get("current_working_directory", build)
                for f in doc["files"]:
                    path = os.path.normpath(os.path.join(cwd, f["file"]))
                    if not path.startswith(host):
                        continue
                    rel = os.path.relpath(path, source)
                    covered.update(f"{rel}:{ln['line_number']}" for ln in f["lines"]
                                   if ln["count"] > 0)
    os.makedirs(os.path.dirname(cache), exist_ok=True)
    with open(cache + ".tmp", "w") as fh:
        fh.write("".join(line + "\n" for line in sorted(covered)))
    os.replace(cache + ".tmp", cache)
    return num, covered, missing


def read_lines(args, tests):
    """Every test's host lines, gcov running on as many runs at once as there are cores."""
    by_num = {t["num"]: name for name, t in tests.items()}
    missing = 0
    with concurrent.futures.ProcessPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        jobs = [pool.submit(lines_of_run, args.data, args.build, args.source, num)
                for num in by_num]
        for job in concurrent.futures.as_completed(jobs):
            num, lines, miss = job.result()
            tests[by_num[num]]["lines"] = lines
            missing += miss
    if missing:
        print(f"warning: {missing} .gcda files had no .gcno in {args.data}/gcno and were skipped",
              file=sys.stderr)


def greedy_cover(gpu, target):
    """The GPU tests that cover the target, greedily by new lines per second, then pruned."""
    left, chosen = set(target), []
    for limit in TIERS:
        while left:
            best, best_key = None, None
            for name in sorted(gpu):
                t = gpu[name]
                if name in chosen or t["secs"] > limit:
                    continue
                gain = len(t["lines"] & left)
                key = (gain / max(t["secs"], MIN_SECONDS), -t["secs"])
                if gain and (best_key is None or key > best_key):
                    best, best_key = name, key
            if best is None:
                break
            chosen.append(best)
            left -= gpu[best]["lines"]
    # A test taken early can be made redundant by later ones: drop those, the slowest first.
    for name in sorted(chosen, key=lambda n: -gpu[n]["secs"]):
        others = set().union(*(gpu[o]["lines"] for o in chosen if o != name))
        if not (gpu[name]["lines"] & target) - others:
            chosen.remove(name)
    return chosen


def by_gain(gpu, chosen, target):
    """The chosen tests reordered by how many target lines each adds to those before it."""
    rest, got, order = list(chosen), set(), []
    while rest:
        name = max(rest, key=lambda n: (len((gpu[n]["lines"] & target) - got), -gpu[n]["secs"],
                                        n))
        order.append((name, len((gpu[name]["lines"] & target) - got)))
        got |= gpu[name]["lines"] & target
        rest.remove(name)
    return order


def file_of(line):
    return line.rsplit(":", 1)[0]


def folder_of(line):
    return os.path.dirname(file_of(line))


def percent(part, whole):
    return 100.0 * part / whole if whole else 100.0


def print_summary(data, tests, target, host_lines, gpu_lines, chosen, quick, gpu):
    driver = ""
    if os.path.exists(os.path.join(data, "driver.txt")):
        with open(os.path.join(data, "driver.txt")) as fh:
            driver = f" on {fh.read().strip()}"
    n_gpu = sum(t["gpu"] for t in tests.values())
    print(f"== summary\nran {len(tests)} tests{driver}: {len(tests) - n_gpu} host, {n_gpu} gpu*,"
          f" {sum(t['secs'] for t in tests.values()):.0f} s")
    for name, t in sorted(tests.items()):
        if t["status"] == "TIMEOUT":
            print(f"  stopped at the timeout: {name} ({t['label']}) after {t['secs']:.0f} s: the"
                  f" lines only it runs are not in the target")
        elif t["status"] != "PASS":
            print(f"  did not pass: {name} ({t['label']}): {t['status']} after {t['secs']:.1f} s"
                  f" (log: {data}/logs/{t['num']}.log)")
    print(f"host lines run by host tests {len(host_lines)}, by GPU tests {len(gpu_lines)};"
          f" target (by GPU tests only) {len(target)}")
    covered = set().union(*(gpu[n]["lines"] for n in chosen)) & target
    quick_covered = set().union(*(gpu[n]["lines"] for n in quick)) & target
    print(f"chosen {len(chosen)} GPU tests, {sum(gpu[n]['secs'] for n in chosen):.1f} s: target"
          f" covered {len(covered)}/{len(target)} ({percent(len(covered), len(target)):.1f}%);"
          f" the quick {len(quick)}: {percent(len(quick_covered), len(target)):.1f}% in"
          f" {sum(gpu[n]['secs'] for n in quick):.1f} s")
    print("per host folder: target lines, covered by the chosen set, by the quick set")
    for d in sorted({folder_of(line) for line in target}):
        tg = {line for line in target if folder_of(line) == d}
        cells = [f"{len(tg & c):6d} ({percent(len(tg & c), len(tg)):5.1f}%)"
                 for c in (covered, quick_covered)]
        print(f"  {d:24s} {len(tg):6d} {cells[0]} {cells[1]}")
    return covered


def print_chosen(order, gpu, target):
    print("\n== the chosen tests, by the target lines each adds to those above it"
          "\n   (+lines, cumulative %, seconds, cumulative seconds; the files only it covers)")
    names = [n for n, _ in order]
    got, acc = set(), 0.0
    for k, (name, gain) in enumerate(order, 1):
        t = gpu[name]
        got |= t["lines"] & target
        acc += t["secs"]
        others = set().union(*(gpu[o]["lines"] for o in names if o != name))
        alone = collections.Counter(file_of(line)[len("host/"):]
                                    for line in (t["lines"] & target) - others)
        files = ", ".join(f"{f}({c})" for f, c in sorted(alone.items(), key=lambda fc: (-fc[1],
                                                                                  fc[0])))
        print(f"  {k:2d} {name}\n     +{gain}, {percent(len(got), len(target)):.1f}%,"
              f" {t['secs']:.2f} s, {acc:.1f} s; alone: {files or '-'}")


def print_missed(target, covered, gpu):
    """Target lines no test within the tiers reaches: name the (slow) tests that do."""
    missed = target - covered
    if not missed:
        return
    print(f"\n== {len(missed)} target lines that only tests slower than {TIERS[-1]:.0f} s run")
    for f, c in collections.Counter(file_of(line) for line in missed).most_common():
        lines = {line for line in missed if file_of(line) == f}
        who = sorted((n for n in gpu if gpu[n]["lines"] & lines), key=lambda n: gpu[n]["secs"])
        print(f"  {f}: {c} lines; run by " +
              ", ".join(f"{n} ({gpu[n]['secs']:.0f} s)" for n in who[:3]))


def cmake_list(var, items, width=100):
    """set(VAR a b ...) as tests/CMakeLists.txt writes it: names filled into 100 columns."""
    if not items:
        return f"set({var})"
    out, line = [f"set({var}"], "   "
    for i, item in enumerate(items):
        word = item + (")" if i == len(items) - 1 else "")
        if len(line) + 1 + len(word) > width and line.strip():
            out.append(line)
            line = "   "
        line += " " + word
    out.append(line)
    return "\n".join(out)


def main():
    args = parse_args()
    tests = read_results(args.data)
    read_lines(args, tests)
    gpu = {n: t for n, t in tests.items() if t["gpu"]}
    host_lines = set().union(*(t["lines"] for t in tests.values() if not t["gpu"]))
    gpu_lines = set().union(*(t["lines"] for t in gpu.values()))
    target = gpu_lines - host_lines
    # Only GPU-labelled tests can add target lines (a host test's lines are not in it), so a
    # host-labelled test is never chosen: it runs under the sanitizers already.
    chosen = greedy_cover({n: t for n, t in gpu.items() if t["gtest"]}, target)
    order = by_gain(gpu, chosen, target)
    names = [n for n, _ in order]
    quick, rest = names[:QUICK], names[QUICK:]
    covered = print_summary(args.data, tests, target, host_lines, gpu_lines, chosen, quick, gpu)
    print_chosen(order, gpu, target)
    print_missed(target, covered, gpu)
    print("\n== for tests/CMakeLists.txt")
    # The list kept is of the GPU tests left out, so that a GPU test added later runs under the
    # sanitizers until this is measured again.
    left_out = sorted(n for n, t in gpu.items() if t["gtest"] and n not in chosen)
    print(cmake_list("rtvk_quick_tests", quick))
    print(cmake_list("rtvk_unsanitized_gpu_tests", left_out))
    return 1 if any(t["status"] not in ("PASS", "TIMEOUT") for t in tests.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
