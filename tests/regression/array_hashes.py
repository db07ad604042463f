#!/usr/bin/env python3
"""Hashes of every number punchsweep wrote into a folder of regression outputs.

For each HDF5 map (*.h5) every dataset is read with h5py, data variables and coordinate
variables alike, and hashed as

    sha256(dtype.str | shape | the array's raw bytes in C order)

so a change of any value, of any bit of a NaN, of the type or of the shape changes the hash.
For each `punchsweep point` JSON file (*.json) the hash is sha256 of the file's bytes.

Attributes are hashed separately ("attributes"), with the volatile ones left out (run time,
command line, version; see VOLATILE_GLOBAL_ATTRIBUTES). They are informational: the
regression check reports their changes but does not fail on them.

Usage: array_hashes.py OUTDIR [-o FILE.json]
Prints (or writes) {"arrays": {file: {dataset: sha256} | sha256}, "attributes": {file: {...}}}.
"""
import argparse
import hashlib
import json
import os
import sys

import h5py
import numpy as np

# Global attributes that change from run to run, or with the binary's identity, without any
# number of the map changing.
VOLATILE_GLOBAL_ATTRIBUTES = {"history", "source", "config", "ranks", "wall_seconds", "points_per_second"}


def array_digest(value):
    """sha256 over dtype, shape and the raw C-order bytes of an array (or a scalar)."""
    a = np.ascontiguousarray(np.asarray(value))
    h = hashlib.sha256()
    h.update(a.dtype.str.encode())
    h.update(b"|")
    h.update(json.dumps(list(a.shape)).encode())
    h.update(b"|")
    if a.dtype.hasobject:  # variable-length strings and the like: hash their text
        h.update(json.dumps([x.decode() if isinstance(x, bytes) else str(x) for x in a.ravel()]).encode())
    else:
        h.update(a.tobytes(order="C"))
    return h.hexdigest()


def attribute_digest(value):
    if isinstance(value, bytes):
        return hashlib.sha256(b"bytes|" + value).hexdigest()
    if isinstance(value, str):
        return hashlib.sha256(b"str|" + value.encode()).hexdigest()
    return array_digest(value)


# Attributes that hold object references (dimension-scale bookkeeping: file addresses, not
# numbers, which may legitimately move).
REFERENCE_ATTRIBUTES = {"DIMENSION_LIST", "REFERENCE_LIST"}


def _attributes(obj, path, out, skip=()):
    for name in sorted(obj.attrs.keys()):
        if name in skip or name in REFERENCE_ATTRIBUTES:
            continue
        try:
            out[f"{path}@{name}"] = attribute_digest(obj.attrs[name])
        except Exception as e:  # an attribute h5py cannot read: record that, do not fail
            out[f"{path}@{name}"] = f"unreadable: {type(e).__name__}"


def hash_map(path):
    """({dataset path: digest}, {path@attribute: digest}) of one HDF5 file."""
    arrays, attributes = {}, {}
    with h5py.File(path, "r") as f:
        _attributes(f, "/", attributes, skip=VOLATILE_GLOBAL_ATTRIBUTES)

        def visit(name, obj):
            if isinstance(obj, h5py.Dataset):
                arrays["/" + name] = array_digest(obj[()])
                _attributes(obj, "/" + name, attributes)
            elif isinstance(obj, h5py.Group):
                _attributes(obj, "/" + name, attributes)

        f.visititems(visit)
    return dict(sorted(arrays.items())), attributes


def hash_file_bytes(path):
    with open(path, "rb") as fh:
        return hashlib.sha256(fh.read()).hexdigest()


def hash_outputs(folder):
    """The hashes of every *.h5 and *.json file in folder (not recursive)."""
    result = {"arrays": {}, "attributes": {}}
    for name in sorted(os.listdir(folder)):
        full = os.path.join(folder, name)
        if not os.path.isfile(full):
            continue
        if name.endswith(".h5"):
            arrays, attributes = hash_map(full)
            result["arrays"][name] = arrays
            result["attributes"][name] = attributes
        elif name.endswith(".json"):
            result["arrays"][name] = hash_file_bytes(full)
    return result


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir", help="a folder written by make_outputs.sh")
    parser.add_argument("-o", "--output", help="write the JSON here instead of stdout")
    args = parser.parse_args()
    if not os.path.isdir(args.outdir):
        print(f"array_hashes.py: {args.outdir} is not a folder", file=sys.stderr)
        return 2
    text = json.dumps(hash_outputs(args.outdir), indent=1, sort_keys=True) + "\n"
    if args.output:
        with open(args.output, "w") as fh:
            fh.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
