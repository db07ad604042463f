#!/usr/bin/python3
"""Copies a sweep's config into a run folder so that the folder runs, resumes and documents
itself: RUN/config.ini, with every file the config names (a path taken from the config's
own folder when relative, as the engine takes it) copied and the key rewritten to the copy:
[model] material to RUN/materials/, a texture's [texture] cell and height_map to
RUN/inputs/. A regime map's identity holds the materials' content, not their paths, so the
copy resumes a map begun from the original; a texture's map is begun from the copy.

  jobs/record_config.py CONFIG.ini RUN_FOLDER

Exit code 2, nothing written, for a config or material file that cannot be read or two
material files of the same name (the engine labels a material axis by file name).
"""
from __future__ import annotations

import shutil
import sys
from pathlib import Path


# The keys that name files, by (section, key), and the run folder's folder for their copies.
FILE_KEYS = {("model", "material"): "materials", ("texture", "cell"): "inputs", ("texture", "height_map"): "inputs"}


def fail(message: str) -> int:
    print(f"record_config.py: error: {message}", file=sys.stderr)
    return 2


def main(argv: list[str]) -> int:
    if len(argv) != 2:
        return fail("usage: record_config.py CONFIG.ini RUN_FOLDER")
    config, run = Path(argv[0]).resolve(), Path(argv[1])
    try:
        lines = config.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as e:
        return fail(f"cannot read the config {config}: {e}")
    section, out, copies = "", [], {}
    for line in lines:
        stripped = line.partition("#")[0].strip()  # "[texture]   # a mould" is a section too
        if stripped.startswith("[") and stripped.endswith("]"):
            section = stripped[1:-1].strip()
        key, eq, rest = line.partition("=")
        folder = FILE_KEYS.get((section, key.strip())) if eq else None
        if folder:
            value, hash_, comment = rest.partition("#")
            files = []
            for item in (v.strip() for v in value.split(",")):
                if not item:
                    continue
                source = Path(item).expanduser()
                source = source if source.is_absolute() else config.parent / source
                if not source.is_file():
                    return fail(f"{config}: [{section}] {key.strip()} = {item}: no such file {source}")
                copy = f"{folder}/{source.name}"
                if copy in copies and copies[copy] != source.resolve():
                    return fail(f"{config}: two {'material' if folder == 'materials' else 'input'} files are named {source.name}")
                copies[copy] = source.resolve()
                files.append(copy)
            line = f"{key.strip()} = {', '.join(files)}   # copied from {value.strip()}" + (
                f"  ({comment.strip()})" if hash_ and comment.strip() else "")
        out.append(line)
    run.mkdir(parents=True, exist_ok=True)
    for copy, source in copies.items():
        (run / copy).parent.mkdir(exist_ok=True)
        shutil.copyfile(source, run / copy)
    (run / "config.ini").write_text("\n".join(out) + "\n", encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
