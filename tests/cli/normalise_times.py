#!/usr/bin/python3
"""Prints a file of tests/cli/test_cli_reference.sh with its times blanked, the one thing allowed to differ
between two runs of the same command (the reproductions have no --no-timing):
- CSV (and field --diagnose's row): the columns named seconds* and megapixels_per_second emptied; in a
  summary (header ...,statistic,realizations,mean,sd,standard_error) the numbers of a seconds* statistic;
- table1 and table2's Markdown and plain text, which put times in most rows: every number as '#' and runs of spaces (and of dashes) as
  one (the plain text aligns its columns to the numbers' widths), so the words and the rows are compared (table1.csv and table2.csv hold their numbers, compared above);
  a verdict on a claim about time ("... and in time (# s vs # s): holds at #") depends on the machine's load, so it is '<verdict>';
- the other reproductions' Markdown and plain text: 'N s' as '<time>';
- in both, the machine the times were measured on ("on <CPU model> (N hardware threads)", "of <CPU model> (...)",
  from core/machine.cpp) as '<machine>': the CPU's name is the host's, not the program's (an Intel host failed
  the comparison recorded on an AMD one); test_cli_reference.sh checks this with another CPU name injected;
- everything else (PNG, NPY, the other text) byte for byte.
Usage: normalise_times.py PATH (relative to the folder the commands ran in)."""
import re
import sys

TIME_COLUMN = re.compile(r"^(seconds.*|megapixels_per_second)$")
NUMBER = re.compile(r"\d+(\.\d+)?(e[-+]?\d+)?")
THREADS = re.compile(r" \((\d+|#) hardware threads\)")
MACHINE_LEAD = re.compile(r"\b(on|of) ")


def blank_machine(text):
    """Each "<lead> <model> (N hardware threads)" as "<lead> <machine> (N hardware threads)", where <lead> is the
    last "on " or "of " before the count on its line: a CPU's model may hold any character but a line break
    ("Intel(R) Xeon(R) Gold 6248 CPU @ 2.50GHz"), while the sentences around it never put "on" or "of" inside it."""
    out = []
    for line in text.split("\n"):
        pieces, start = [], 0
        for threads in THREADS.finditer(line):
            leads = list(MACHINE_LEAD.finditer(line, start, threads.start()))
            if leads:
                pieces.append(line[start:leads[-1].end()] + "<machine>")
                start = threads.start()
        out.append("".join(pieces) + line[start:])
    return "\n".join(out)


def main():
    path = sys.argv[1].removeprefix("./")
    data = open(path, "rb").read()
    name = path.rsplit("/", 1)[-1]
    if path.endswith(".csv") and data.decode().split("\n", 1)[0].endswith(",statistic,realizations,mean,sd,standard_error"):
        # A summary (--summary, table1_summary.csv): the rows of a time column get their numbers blanked.
        import csv
        import io
        rows = list(csv.reader(io.StringIO(data.decode())))
        statistic = rows[0].index("statistic")
        for row in rows[1:]:
            if len(row) > statistic and TIME_COLUMN.match(row[statistic]):
                row[-3:] = ["", "", ""]
        out = io.StringIO()
        csv.writer(out, lineterminator="\n").writerows(rows)
        sys.stdout.write(out.getvalue())
    elif path.endswith(".csv") or name == "field_diagnose.stdout":
        lines = data.decode().split("\n")
        header = lines[0].split(",")
        blank = [i for i, column in enumerate(header) if TIME_COLUMN.match(column)]
        if blank and '"' not in data.decode():
            for k in range(1, len(lines)):
                fields = lines[k].split(",")
                if len(fields) == len(header):
                    for i in blank:
                        fields[i] = ""
                lines[k] = ",".join(fields)
        elif blank:  # a quoted field may hold commas: blank from the first unquoted split, by count
            import csv
            import io
            rows = list(csv.reader(io.StringIO(data.decode())))
            for row in rows[1:]:
                for i in blank:
                    if i < len(row):
                        row[i] = ""
            out = io.StringIO()
            csv.writer(out, lineterminator="\n").writerows(rows)
            sys.stdout.write(out.getvalue())
            return
        sys.stdout.write("\n".join(lines))
    elif path in ("r1/table1.md", "table1.stdout", "r2/table2.md", "table2.stdout"):
        text = re.sub(r"-{2,}", "--", re.sub(r"[ \t]+", " ", NUMBER.sub("#", data.decode())))
        text = "\n".join(re.sub(r"(DOES NOT hold|holds)", "<verdict>", line) if "in time (" in line else line
                          for line in text.split("\n"))
        sys.stdout.write(blank_machine(text))
    elif path in ("r3/cnj_study.md", "cnj_study.stdout", "r4/integration.md", "integration.stdout"):
        sys.stdout.write(blank_machine(re.sub(r"\b\d+(\.\d+)?(e[-+]?\d+)? s\b", "<time>", data.decode())))
    else:
        sys.stdout.buffer.write(data)


main()
