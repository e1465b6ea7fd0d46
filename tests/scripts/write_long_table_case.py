#!/usr/bin/python3
"""Writes tiny_case.yaml with its inflow elevation as an inline table of ROWS rows, and the same
table as a CSV file beside it with a case that reads it (issue 39 item 10: a long case costs
about 110 bytes of memory per byte of text; a table from a file 16 bytes per row).

    write_long_table_case.py TINY_CASE OUT_FOLDER ROWS
"""
import os
import sys

tiny, out, rows = sys.argv[1], sys.argv[2], int(sys.argv[3])
os.makedirs(out, exist_ok=True)
text = open(tiny).read()
inline = "    inflow: {type: elevation, value: 4.0}"
assert inline in text
table = ", ".join(f"[{k * 0.5}, 4.0]" for k in range(rows))
with open(os.path.join(out, "long_table.yaml"), "w") as f:
    f.write(text.replace(inline, f"    inflow:\n      type: elevation\n      value: [{table}]"))
with open(os.path.join(out, "long_table.csv"), "w") as f:
    f.write("t [s],eta [m]\n")
    f.writelines(f"{k * 0.5},4.0\n" for k in range(rows))
with open(os.path.join(out, "long_table_file.yaml"), "w") as f:
    f.write(text.replace(inline, "    inflow: {type: elevation, value: {file: long_table.csv}}"))
