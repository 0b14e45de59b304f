#!/usr/bin/env python3
"""Every claim of results/claims.csv can be found from its id (issue: greppable claims).

A claim `<paper>.<local>` is checked by experiments/<paper>/<artifact>.cpp. Its local id is either
written there whole, as the string literal "<local>", or assembled at run time from a stem: then
the longest prefix of <local> that the experiment writes as a whole string literal "<stem>" must
be written exactly once, at the line that assembles the family. `grep -rn '"<stem>"'
experiments/<paper>/` then finds that line. Prints the claims that break the rule; exit 1 if any.
Usage: scripts/check-claim-ids.py [ROOT]
"""
import csv
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
literals_of = {}
bad = []
claims = list(csv.DictReader(open(os.path.join(root, "results", "claims.csv"), encoding="utf-8")))
for row in claims:
    paper, artifact, claim = row["paper"], row["artifact"], row["claim"]
    local = claim[len(paper) + 1:]
    path = os.path.join(root, "experiments", paper, artifact + ".cpp")
    if path not in literals_of:
        literals_of[path] = re.findall(r'"((?:[^"\\\n]|\\.)*)"', open(path, encoding="utf-8").read())
    literals = literals_of[path]
    if local in literals:
        continue
    stems = [s for s in set(literals) if s and local.startswith(s)]
    if not stems:
        bad.append(f"{claim}: no string literal of {path} starts it")
        continue
    stem = max(stems, key=len)
    if literals.count(stem) != 1:
        bad.append(f"{claim}: its stem \"{stem}\" is written {literals.count(stem)} times in {path}")
for b in bad:
    print(b)
print(f"claim ids: {len(claims)} claims, {len(bad)} not traceable to one line")
sys.exit(1 if bad else 0)
