#!/usr/bin/env python3
"""The glyph outlines of the interpolant benchmark: the on-curve points of letters of DejaVu Sans.

    /usr/bin/python3 scripts/glyph_points.py OUT_DIR [FONT]

writes OUT_DIR/dejavu-sans-<glyph>-<contour>.csv, one closed contour each: the points a TrueType
outline flags as on the curve, in the font's order and units (1/2048 em), with the font, its
version, the Debian package and fontTools' version in the header. The committed files in
reference/benchmark/glyphs/ were made by this script (reference/benchmark/classic_data.csv lists
them); the test benchmark.glyph_points_regenerate runs it again and compares.

Needs python3-fonttools and fonts-dejavu-core (scripts/install-deps.sh test).
"""
import os
import subprocess
import sys

from fontTools import version as fonttools_version
from fontTools.ttLib import TTFont

FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
PACKAGE = "fonts-dejavu-core"
# (character, contour index): the contours with at least 8 on-curve points among letters with
# curved outlines.
CONTOURS = [("S", 0), ("C", 0), ("a", 1), ("e", 0), ("g", 1), ("2", 0), ("8", 1)]


def package_version(package):
    try:
        out = subprocess.run(["dpkg-query", "-W", "-f=${Version}", package], capture_output=True, text=True, check=True)
        return out.stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def main(argv):
    if len(argv) not in (2, 3):
        sys.stderr.write("usage: glyph_points.py OUT_DIR [FONT]\n")
        return 2
    out_dir = argv[1]
    font_path = argv[2] if len(argv) == 3 else FONT
    font = TTFont(font_path)
    family = font["name"].getDebugName(1)
    version = font["name"].getDebugName(5)
    units = font["head"].unitsPerEm
    cmap = font.getBestCmap()
    glyf = font["glyf"]
    os.makedirs(out_dir, exist_ok=True)
    for char, contour in CONTOURS:
        name = cmap[ord(char)]
        coordinates, ends, flags = glyf[name].getCoordinates(glyf)
        start = 0 if contour == 0 else ends[contour - 1] + 1
        points = [coordinates[i] for i in range(start, ends[contour] + 1) if flags[i] & 1]
        path = os.path.join(out_dir, "dejavu-sans-%s-%d.csv" % (name, contour))
        with open(path, "w", encoding="utf-8") as f:
            f.write("# source: the on-curve points of contour %d of the glyph \"%s\" (U+%04X) of the font %s, %s\n" % (contour, name, ord(char), family, version))
            f.write("# font file %s (Debian %s %s), read with fontTools %s by scripts/glyph_points.py\n"
                    % (os.path.basename(font_path), PACKAGE, package_version(PACKAGE), fonttools_version))
            f.write("# units: 1/%d em; a closed contour in the font's order (the off-curve points left out)\n" % units)
            f.write("x,y\n")
            for x, y in points:
                f.write("%d,%d\n" % (x, y))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
