#!/usr/bin/env python3
"""Checks that cfd/ keeps its rooms: a file includes only headers of its own room or of rooms below it (the
order of ROOMS, as cfd/CMakeLists.txt lists them), every include of a project header is folder-qualified
("cfd/<room>/<file>"), and every file of cfd/ lies in a known room. In particular the linear algebra
(cfd/linear) cannot include the gas settings (cfd/solver). Exit 1 with one line per broken include.

usage: check_rooms.py [CFD_FOLDER]"""
import os
import re
import sys
import tempfile

ROOMS = ["base", "io", "geometry", "mesh", "linear", "fv", "solver", "output"]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def problems(cfd):
    found = []
    known = {name for room in ROOMS if os.path.isdir(os.path.join(cfd, room))
             for name in os.listdir(os.path.join(cfd, room))}
    for folder, _, files in os.walk(cfd):
        for name in sorted(files):
            if not name.endswith((".hpp", ".cpp", ".h")):
                continue
            path = os.path.join(folder, name)
            relative = os.path.relpath(path, cfd)
            parts = relative.split(os.sep)
            if len(parts) != 2 or parts[0] not in ROOMS:
                found.append(f"{relative}: not in a room of cfd/ (allowed: {', '.join(ROOMS)})")
                continue
            rank = ROOMS.index(parts[0])
            for header in INCLUDE.findall(open(path).read()):
                target = header.split("/")
                if target[0] != "cfd":
                    if len(target) == 1 and header in known:
                        found.append(f"{relative}: includes \"{header}\" without its folder (write \"cfd/<room>/...\")")
                    elif len(target) > 1 and target[0] in ("coupling", "liggghts_plugins", "tests"):
                        found.append(f"{relative}: includes \"{header}\", outside cfd/ (the gas solver stands alone)")
                    continue
                if len(target) != 3 or target[1] not in ROOMS:
                    found.append(f"{relative}: includes \"{header}\", not a header of a cfd/ room")
                elif ROOMS.index(target[1]) > rank:
                    found.append(f"{relative}: room {parts[0]} includes \"{header}\" of room {target[1]}, "
                                 f"which is above it ({' < '.join(ROOMS)})")
    return found


def self_test():
    """The check finds each kind of broken include in a small made-up tree."""
    with tempfile.TemporaryDirectory() as cfd:
        for room, name, text in [("base", "types.hpp", ""),
                                 ("linear", "krylov.hpp", '#include "cfd/solver/settings.hpp"\n#include "types.hpp"\n'),
                                 ("solver", "settings.hpp", '#include "cfd/base/types.hpp"\n'),
                                 ("solver", "gas.cpp", '#include "coupling/run/x.hpp"\n#include "cfd/mesh.hpp"\n')]:
            os.makedirs(os.path.join(cfd, room), exist_ok=True)
            open(os.path.join(cfd, room, name), "w").write(text)
        open(os.path.join(cfd, "loose.hpp"), "w").write("")
        found = problems(cfd)
        expected = ["linear/krylov.hpp: room linear includes \"cfd/solver/settings.hpp\"",
                    "linear/krylov.hpp: includes \"types.hpp\" without its folder",
                    "solver/gas.cpp: includes \"coupling/run/x.hpp\", outside cfd/",
                    "solver/gas.cpp: includes \"cfd/mesh.hpp\", not a header of a cfd/ room",
                    "loose.hpp: not in a room"]
        missing = [e for e in expected if not any(line.startswith(e) for line in found)]
        if missing or len(found) != len(expected):
            sys.exit(f"FAIL: the check itself: expected {expected}, found {found}")


def main():
    self_test()
    cfd = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                             "..", "..", "..", "cfd")
    found = problems(os.path.normpath(cfd))
    for line in found:
        print(line)
    if found:
        sys.exit(1)
    print("PASS: every include in cfd/ stays in its room or goes down")


if __name__ == "__main__":
    main()
