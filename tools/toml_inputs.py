#!/usr/bin/python3
"""The files a wing or case file depends on, for the make targets (tools/model.mk,
tools/pipeline.mk):

    toml_inputs.py wing WING.toml   the wing file and every file it names (outline_file)
    toml_inputs.py case CASE.toml   make variable assignments: CASE_NAME, CASE_KIND,
                                    CASE_WING, CASE_CHAIN (paths as seen from here),
                                    CASE_BODIES (structure.bodies, if an integer)

Paths in a file are relative to its folder (docs/wing_file.md, docs/case_file.md).
A file that cannot be read prints nothing and exits 0: flapsim itself then reports it."""
import os
import sys
import tomllib


def load(path):
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError):
        return None


def near(path, name):
    return os.path.normpath(os.path.join(os.path.dirname(path), name))


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("wing", "case"):
        sys.exit(__doc__)
    kind, path = sys.argv[1], sys.argv[2]
    data = load(path)
    if kind == "wing":
        files = [path]
        outline = (data or {}).get("planform", {}).get("outline_file")
        if isinstance(outline, str):
            files.append(near(path, outline))
        print(" ".join(files))
        return
    if data is None:
        return
    name = data.get("name") or os.path.splitext(os.path.basename(path))[0]
    wing = data.get("wing")
    chain = data.get("chain")
    print(f"CASE_NAME={name}")
    print(f"CASE_KIND={data.get('structure', {}).get('kind', 'rigid')}")
    print(f"CASE_WING={near(path, wing) if isinstance(wing, str) else ''}")
    print(f"CASE_CHAIN={near(path, chain) if isinstance(chain, str) else ''}")
    bodies = data.get("structure", {}).get("bodies")
    print(f"CASE_BODIES={bodies if isinstance(bodies, int) and not isinstance(bodies, bool) else ''}")


if __name__ == "__main__":
    main()
