#!/usr/bin/env python3
"""Compares a written workbook's layout with the contest's template, cell for cell.

usage: check_workbook.py WRITTEN TEMPLATE VALUES_CSV
Sheet names and order, every label in column A, every header in row 1 and the sheet sizes must
be identical; every value cell must hold the number in VALUES_CSV (sheet,row,col,value), which the
test computed from the library, already rounded to 6 decimals.
"""
import csv
import sys

import openpyxl


def main() -> int:
    written, template, values = sys.argv[1:4]
    w = openpyxl.load_workbook(written)
    t = openpyxl.load_workbook(template)
    problems = []
    if w.sheetnames != t.sheetnames:
        problems.append(f"sheets {w.sheetnames} != template {t.sheetnames}")
    for name in t.sheetnames:
        if name not in w.sheetnames:
            continue
        ws, ts = w[name], t[name]
        if (ws.max_row, ws.max_column) != (ts.max_row, ts.max_column):
            problems.append(f"{name}: size {ws.max_row}x{ws.max_column} != {ts.max_row}x{ts.max_column}")
        for r in range(1, ts.max_row + 1):
            if ws.cell(r, 1).value != ts.cell(r, 1).value:
                problems.append(f"{name}!A{r}: {ws.cell(r, 1).value!r} != {ts.cell(r, 1).value!r}")
        for c in range(1, ts.max_column + 1):
            if ws.cell(1, c).value != ts.cell(1, c).value:
                problems.append(f"{name} row 1 col {c}: {ws.cell(1, c).value!r} != {ts.cell(1, c).value!r}")
    checked = 0
    with open(values, newline="") as f:
        for sheet, row, col, value in csv.reader(f):
            got = w[sheet].cell(int(row), int(col)).value
            if not isinstance(got, (int, float)) or abs(got - float(value)) > 1e-12:
                problems.append(f"{sheet} r{row} c{col}: {got!r} != {value}")
            checked += 1
    for p in problems[:20]:
        print(p)
    print(f"{checked} values checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
