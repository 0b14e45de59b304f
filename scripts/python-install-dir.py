#!/usr/bin/env python3
"""Prints where `cmake --install` puts the Python package cagd, relative to the install prefix
(argv[1]), for the interpreter running this script: the directory of its own sysconfig scheme that
lies under the prefix, so that the installed package imports without PYTHONPATH.

- Debian's deb_system scheme for the interpreter's own prefix (/usr: lib/python3/dist-packages);
- the default scheme's platlib, when it lies under the prefix (Debian's python3 and
  PREFIX=/usr/local: lib/python3.11/dist-packages, which that python3 searches);
- otherwise the posix_prefix scheme under the prefix (lib/python3.11/site-packages), which an
  interpreter searches only when told (PYTHONPATH, a .pth file).
"""
import os
import sys
import sysconfig

prefix = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else sys.prefix
default = sysconfig.get_path("platlib")
if os.path.abspath(sys.prefix) == prefix and "deb_system" in sysconfig.get_scheme_names():
    path = sysconfig.get_path("platlib", "deb_system")
elif os.path.commonpath([default, prefix]) == prefix:
    path = default
else:
    path = sysconfig.get_path("platlib", "posix_prefix", vars={"base": prefix, "platbase": prefix})
print(os.path.relpath(path, prefix))
