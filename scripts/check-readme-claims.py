#!/usr/bin/env python3
"""README.md's table of the papers (between <!-- claims:begin --> and <!-- claims:end -->) gives,
per paper, the counts of the paper's claims and of each status in results/claims.csv, and the
number of claims of ours (origin "ours", counted apart). A run never rewrites
the README: this check fails while the two differ, naming the paper and the column.
Usage: check-readme-claims.py [ROOT]
"""
import collections
import csv
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
counts = collections.defaultdict(collections.Counter)
with open(os.path.join(root, "results", "claims.csv"), encoding="utf-8") as f:
    for row in csv.DictReader(f):
        if row.get("origin") == "ours":  # our own statements are counted apart (column "ours")
            counts[row["paper"]]["ours"] += 1
            continue
        counts[row["paper"]]["claims"] += 1
        counts[row["paper"]][row["status"]] += 1

readme = open(os.path.join(root, "README.md"), encoding="utf-8").read()
block = re.search(r"<!-- claims:begin -->\n(.*?)<!-- claims:end -->", readme, re.S)
if not block:
    sys.exit("README.md: no <!-- claims:begin --> ... <!-- claims:end --> table")
lines = [l for l in block.group(1).splitlines() if l.startswith("|")]
header = [c.strip() for c in lines[0].strip("|").split("|")]
columns = {"claims": "claims", "reproduced": "reproduced", "deviates": "deviates", "depends": "depends", "failed": "failed", "ours": "ours"}
problems, seen = [], set()
for line in lines[2:]:
    cells = [c.strip() for c in line.strip("|").split("|")]
    paper = re.search(r"`([a-z_0-9]+)`", cells[0]).group(1)
    seen.add(paper)
    for name, cell in zip(header[1:], cells[1:]):
        want = counts[paper][columns[name]]
        if int(cell) != want:
            problems.append(f"README.md: {paper} {name} is {cell}, results/claims.csv has {want}")
for paper in sorted(set(counts) - seen):
    problems.append(f"README.md: no row for {paper}")
for p in problems:
    print(p)
print(f"README.md's table: {len(seen)} papers, {sum(c['claims'] for c in counts.values())} claims" + ("" if problems else ", as in results/claims.csv"))
sys.exit(1 if problems else 0)
