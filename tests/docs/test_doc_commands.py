#!/usr/bin/python3
"""Every command a document shows is run, and its shown output compared, so the documents cannot drift.

    DFVN_BUILD_DIR=build DFVN_SOURCE_DIR=. tests/docs/test_doc_commands.py [--record] [FILE.md...]

Reads README.md and docs/*.md (or the files given). Every fenced block whose language is `sh` or
`console` is a command block; `python` blocks are programs. In a command block:

- lines starting with "$ " are commands, and the lines after one, up to the next "$ " line, are the
  output it shows: the command's standard output and standard error, compared after both sides are
  normalised (times such as "0.2 s" or "12.3 ms" become "T s"; trailing spaces go);
- a block without "$ " lines is a list of commands, one a line, their output not shown;
- a line ending in "\\" continues on the next line; "#" starts a comment as in sh.

Each command runs with bash -o pipefail in one working folder per document (so a later block reads
what an earlier one wrote), where `build` is the build tree and `dfvn-sample` is on PATH; it must exit 0
and, where output is shown, print it. `python` blocks run with the build's module on PYTHONPATH.

An HTML comment on the line before a block says how it runs:
  <!-- doc-test: skip REASON -->   not run (set-up and installation commands that other tests or CI
                                    run: scripts/run, scripts/test, cmake --install; REASON is printed)
  <!-- doc-test: mpi -->           needs dfvn-sample-mpi (built with -DDFVN_MPI=ON); skipped without it
  <!-- doc-test: exit N -->        every command of the block must exit with status N (an error shown)

Python blocks, and commands that import dfvn, are skipped (and said so) when the build has no Python
package (the sanitizer build).

--record rewrites each shown output with what the command printed (for a change that means it; check
the diff). The test also checks itself: an edited shown output must make it fail.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

SOURCE = os.path.abspath(os.environ.get("DFVN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..")))
BUILD = os.path.abspath(os.environ.get("DFVN_BUILD_DIR", os.path.join(SOURCE, "build")))
# The Python package is built beside the binary unless the build leaves it out (the sanitizer build does:
# an ASan-instrumented extension cannot be loaded by an uninstrumented interpreter).
PYTHON_MODULE = os.path.exists(os.path.join(BUILD, "python", "dfvn", "__init__.py"))
IMPORTS_DFVN = re.compile(r"\bimport\b[^;\n\"']*\bdfvn\b")
TIMEOUT = int(os.environ.get("DFVN_DOC_TIMEOUT", "900"))
FENCE = re.compile(r"^```(\w*)\s*$")
DIRECTIVE = re.compile(r"^<!-- doc-test: (skip .+|mpi|exit \d+) -->$")
TIME = re.compile(r"\b\d+(\.\d+)?( ?)(s|ms|min)\b")


def normalise(text):
    text = TIME.sub(r"T\2\3", text)
    return "\n".join(line.rstrip() for line in text.strip("\n").split("\n"))


def blocks(path):
    """(language, directive, first line number, lines) of every fenced block of a Markdown file."""
    lines = open(path, encoding="utf-8").read().split("\n")
    found, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if m and m.group(1):
            directive = None
            if i > 0 and DIRECTIVE.match(lines[i - 1].strip()):
                directive = DIRECTIVE.match(lines[i - 1].strip()).group(1)
            j = i + 1
            while j < len(lines) and not lines[j].startswith("```"):
                j += 1
            found.append((m.group(1), directive, i + 2, lines[i + 1:j]))
            i = j
        i += 1
    return found


def commands(lines):
    """[(command, shown output or None, index of the first output line, index after it)] of a block."""
    transcript = any(line.startswith("$ ") for line in lines)
    out, i = [], 0
    while i < len(lines):
        line = lines[i]
        if transcript and not line.startswith("$ "):
            i += 1
            continue
        text = line[2:] if transcript else line
        i += 1
        while text.rstrip().endswith(("\\", "|", "&&")) and i < len(lines):
            joined = text.rstrip()
            text = (joined[:-1] if joined.endswith("\\") else joined) + " " + lines[i].strip()
            i += 1
        if not text.strip() or text.strip().startswith("#"):
            continue
        start = i
        if transcript:
            while i < len(lines) and not lines[i].startswith("$ "):
                i += 1
            out.append((text, "\n".join(lines[start:i]), start, i))
        else:
            out.append((text, None, start, start))
    return out


def environment(work):
    env = dict(os.environ)
    bin_dir = os.path.join(work, ".bin")
    os.makedirs(bin_dir, exist_ok=True)
    for program in ("dfvn-sample", "dfvn-sample-mpi"):
        target = os.path.join(BUILD, program)
        if os.path.exists(target) and not os.path.exists(os.path.join(bin_dir, program)):
            os.symlink(target, os.path.join(bin_dir, program))
    env["PATH"] = bin_dir + ":/usr/bin:/bin:" + env.get("PATH", "")
    env["PYTHONPATH"] = os.path.join(BUILD, "python")
    env["TERM"] = "dumb"
    # Open MPI as root in a container (as the MPI tests run it).
    env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_btl="self,vader",
               OMPI_MCA_btl_vader_single_copy_mechanism="none")
    return env


def run_document(path, record, failures, results):
    name = os.path.relpath(path, SOURCE)
    work = tempfile.mkdtemp(prefix="doc-test-")
    try:
        os.symlink(BUILD, os.path.join(work, "build"))
        for extra in ("data", "scripts"):  # commands may read the repository's data and scripts
            os.symlink(os.path.join(SOURCE, extra), os.path.join(work, extra))
        env = environment(work)
        text_lines = open(path, encoding="utf-8").read().split("\n")
        edits = []  # (first line, end line, new lines) for --record
        for language, directive, first, lines in blocks(path):
            if language not in ("sh", "console", "python"):
                continue
            where = f"{name}:{first}"
            if directive and directive.startswith("skip"):
                print(f"skip {where}: {directive[5:]}")
                results["skipped"] += 1
                continue
            if directive == "mpi" and not os.path.exists(os.path.join(BUILD, "dfvn-sample-mpi")):
                print(f"skip {where}: no dfvn-sample-mpi in this build")
                results["skipped"] += 1
                continue
            expected_status = int(directive.split()[1]) if directive and directive.startswith("exit") else 0
            if language == "python" and not PYTHON_MODULE:
                print(f"skip {where}: no Python module in this build (the sanitizer build has none)")
                results["skipped"] += 1
                continue
            if language == "python":
                program = "\n".join(lines)
                r = subprocess.run(["/usr/bin/python3", "-c", program], cwd=work, env=env, capture_output=True, text=True,
                                   timeout=TIMEOUT)
                results["run"] += 1
                ok = r.returncode == 0
                print(f"{'ok  ' if ok else 'FAIL'} {where}: python block")
                if not ok:
                    failures.append(f"{where}: the python block failed: {r.stderr.strip()[-600:]}")
                continue
            for command, shown, start, end in commands(lines):
                if IMPORTS_DFVN.search(command) and not PYTHON_MODULE:
                    print(f"skip {where}: no Python module in this build (the sanitizer build has none)")
                    results["skipped"] += 1
                    continue
                r = subprocess.run(["bash", "-o", "pipefail", "-c", command], cwd=work, env=env, capture_output=True,
                                   text=True, timeout=TIMEOUT)
                results["run"] += 1
                printed = r.stdout + r.stderr
                problems = []
                if r.returncode != expected_status:
                    problems.append(f"exit status {r.returncode}, not {expected_status}: {r.stderr.strip()[-600:]}")
                if shown is not None:
                    results["compared"] += 1
                    results["pairs"].append((shown, printed))
                    if normalise(shown) != normalise(printed):
                        problems.append("its output differs from the shown one:\n" + diff(normalise(shown), normalise(printed)))
                        if record:
                            edits.append((first - 1 + start, first - 1 + end, printed.rstrip("\n").split("\n")))
                print(f"{'ok  ' if not problems else 'FAIL'} {where}: {command[:90]}")
                for p in problems:
                    failures.append(f"{where}: {command}\n    {p}")
        if record and edits:
            for begin, end, new in sorted(edits, reverse=True):
                text_lines[begin:end] = new
            open(path, "w", encoding="utf-8").write("\n".join(text_lines))
            print(f"recorded {len(edits)} output(s) into {name}")
    finally:
        shutil.rmtree(work, ignore_errors=True)


def diff(expected, got):
    import difflib
    return "\n".join(difflib.unified_diff(expected.split("\n"), got.split("\n"), "shown", "printed", lineterm="", n=1))


def main(args):
    record = "--record" in args
    files = [a for a in args if a != "--record"]
    if not files:
        files = [os.path.join(SOURCE, "README.md")] + sorted(
            os.path.join(SOURCE, "docs", f) for f in os.listdir(os.path.join(SOURCE, "docs")) if f.endswith(".md"))
    failures, results = [], {"run": 0, "compared": 0, "skipped": 0, "pairs": []}
    for path in files:
        run_document(path, record, failures, results)
    # The test checks itself: one shown output edited by a character must not compare equal.
    agreeing = [(s, p) for s, p in results["pairs"] if normalise(s) == normalise(p)]
    if agreeing:
        shown, printed = agreeing[0]
        edited = shown.replace("0", "1", 1) if "0" in shown else shown + "x"
        if normalise(edited) == normalise(printed):
            failures.append("self-check: an edited shown output still compares equal")
    if results["compared"] == 0:
        failures.append("no shown output was compared")
    print(f"{results['run']} commands and programs run, {results['compared']} shown outputs compared, "
          f"{results['skipped']} blocks skipped; {len(failures)} failure(s)")
    for f in failures:
        print("FAIL " + f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
