#!/usr/bin/python3
"""Checks that every column of the given CSV files has one type (issue 24, "tidy outputs").

    check_csv_types.py FILE.csv...

Each file is read as RFC 4180 CSV (the csv module: quoted fields may hold commas); its first row is
the header, and every other row must have the header's number of fields. Files with the same header
are one table (the same output of different runs, e.g. field --diagnose at two frequencies), so a
column must keep its type across them too. Every non-empty cell is one of
  integer  optional '-', digits only                            ("3", "-1")
  real     a decimal point or an exponent ("1.0", "2.5e-07", "1e+06"), or "nan", "inf", "-inf"
  word     anything else ("cnj", "mean", "NaN", "time-0.5.png")
and a column's non-empty cells must all have one type; empty cells mean "does not apply" and are
allowed anywhere. A real column written with a number like "1" (no decimal point) beside "0.5" is
thus a column of two types. Prints one line per problem and exits 1 if there is any, else prints a
summary and exits 0.
"""
import csv
import re
import sys

INTEGER = re.compile(r"-?[0-9]+")
REAL = re.compile(r"-?([0-9]+\.[0-9]*|\.[0-9]+|[0-9]+(\.[0-9]*)?[eE][-+]?[0-9]+|[0-9]*\.[0-9]+[eE][-+]?[0-9]+)")
REAL_SPECIAL = {"nan", "inf", "-inf"}  # one spelling each (fmt's)


def cell_type(text):
    if INTEGER.fullmatch(text):
        return "integer"
    if REAL.fullmatch(text) or text in REAL_SPECIAL:
        return "real"
    return "word"


def main(paths):
    problems = []
    tables = {}  # header -> list of (path, line number, row)
    for path in paths:
        with open(path, newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        if not rows:
            problems.append(f"{path}: empty (no header)")
            continue
        header = tuple(rows[0])
        if len(set(header)) != len(header):
            problems.append(f"{path}: a column name appears twice in the header {','.join(header)}")
        if any(cell_type(name) != "word" for name in header):
            problems.append(f"{path}: the first line is not a header of names: {','.join(header)}")
        table = tables.setdefault(header, [])
        for number, row in enumerate(rows[1:], start=2):
            if len(row) != len(header):
                problems.append(f"{path}:{number}: {len(row)} fields, the header has {len(header)}")
                continue
            table.append((path, number, row))
    columns = 0
    for header, rows in tables.items():
        for c, name in enumerate(header):
            columns += 1
            first = {}  # type -> (path, line, text) of its first cell
            for path, number, row in rows:
                text = row[c]
                if text != "":
                    first.setdefault(cell_type(text), (path, number, text))
            if len(first) > 1:
                seen = "; ".join(f"{t} {text!r} ({path}:{number})" for t, (path, number, text) in first.items())
                problems.append(f"column '{name}' has {len(first)} types: {seen}")
    for p in problems:
        print(f"FAIL: {p}")
    if problems:
        return 1
    print(f"{len(paths)} CSV files, {len(tables)} distinct headers, {columns} columns: each of one type")
    return 0


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: check_csv_types.py FILE.csv...")
    sys.exit(main(sys.argv[1:]))
