#!/usr/bin/env python3
"""Regression check: the binary in $PUNCHSWEEP writes exactly the numbers the hashes hold.

Runs make_outputs.sh with $PUNCHSWEEP into a temporary folder, hashes every dataset of every
map and every point JSON file (array_hashes.py), and compares with expected_hashes.json.
Every differing, missing or extra dataset or file is printed, and the exit code is 1.
Attribute changes are printed as notes and never fail the check.

Where a difference is found, the differences are measured (count of differing elements,
max abs and rel difference, where the largest sits) against baseline outputs, taken from
  --baseline-outputs DIR   or env PUNCHSWEEP_BASELINE_OUTPUTS: a folder of make_outputs.sh
                            outputs of the baseline binary, or
  --baseline-binary BIN    or env PUNCHSWEEP_BASELINE: a baseline binary, run on demand.
Without either, only the names are printed.

  --keep DIR        keep the outputs in DIR (they are kept anyway when the check fails)
  --write-expected  regenerate expected_hashes.json from $PUNCHSWEEP, deliberately
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, HERE)
import array_hashes  # noqa: E402

EXPECTED = os.path.join(HERE, "expected_hashes.json")


def make_outputs(binary, folder):
    t0 = time.monotonic()
    proc = subprocess.run(["bash", os.path.join(HERE, "make_outputs.sh"), binary, folder],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    sys.stdout.write(proc.stdout)
    if proc.returncode != 0:
        print(f"FAIL: make_outputs.sh {binary} exited with {proc.returncode}")
        return False
    print(f"outputs written in {time.monotonic() - t0:.1f} s")
    return True


# ----------------------------------------------------------------------------------------
# Measuring a difference, where baseline outputs are at hand.

def _coords(ds, index):
    """'l=0.75, dh=0.05, ...' for a multi-index into a dataset with dimension scales."""
    parts = []
    for axis, i in enumerate(index):
        label = f"dim{axis}"
        value = None
        try:
            dim = ds.dims[axis]
            if len(dim):
                scale = dim[0]
                label = scale.name.lstrip("/")
                value = scale[i]
        except Exception:
            pass
        parts.append(f"{label}={value!r}" if value is not None else f"{label}[{i}]")
    return ", ".join(parts)


def describe_dataset(base_file, new_file, name):
    import h5py
    import numpy as np
    with h5py.File(base_file, "r") as fb, h5py.File(new_file, "r") as fn:
        if name not in fb or name not in fn:
            return "    (not in both files)"
        db, dn = fb[name], fn[name]
        a, b = np.asarray(db[()]), np.asarray(dn[()])
        if a.dtype != b.dtype or a.shape != b.shape:
            return f"    dtype/shape: baseline {a.dtype} {a.shape}, now {b.dtype} {b.shape}"
        if a.dtype.kind not in "fiub":
            return f"    {a.dtype} values differ"
        lines = []
        bits_differ = a.tobytes() != b.tobytes()
        au = a.reshape(-1).view(f"u{a.dtype.itemsize}") if a.dtype.itemsize in (1, 2, 4, 8) else None
        bu = b.reshape(-1).view(f"u{b.dtype.itemsize}") if au is not None else None
        n_bits = int(np.count_nonzero(au != bu)) if au is not None else int(bits_differ)
        if a.dtype.kind == "f":
            an, bn = np.isnan(a), np.isnan(b)
            nan_mismatch = an != bn
            both = ~an & ~bn
            value_diff = (a != b) & both
            n_val = int(np.count_nonzero(value_diff)) + int(np.count_nonzero(nan_mismatch))
            lines.append(f"    {n_val} of {a.size} elements differ in value (NaN == NaN), "
                         f"{n_bits} differ in bits; {int(np.count_nonzero(nan_mismatch))} NaN in one only")
            if np.any(value_diff):
                with np.errstate(invalid="ignore", over="ignore"):
                    d = np.where(value_diff, np.abs(a.astype(np.float64) - b.astype(np.float64)), 0.0)
                    scale = np.maximum(np.abs(a), np.abs(b)).astype(np.float64)
                    r = np.where(value_diff & (scale > 0), d / np.where(scale > 0, scale, 1.0), 0.0)
                ia = np.unravel_index(int(np.nanargmax(d)), a.shape)
                ir = np.unravel_index(int(np.nanargmax(r)), a.shape)
                lines.append(f"    max abs difference {np.nanmax(d):.6g} at ({_coords(dn, ia)}): "
                             f"baseline {a[ia]!r}, now {b[ia]!r}")
                lines.append(f"    max rel difference {np.nanmax(r):.6g} at ({_coords(dn, ir)}): "
                             f"baseline {a[ir]!r}, now {b[ir]!r}")
            if np.any(nan_mismatch):
                i = np.unravel_index(int(np.flatnonzero(nan_mismatch)[0]), a.shape)
                lines.append(f"    first NaN mismatch at ({_coords(dn, i)}): baseline {a[i]!r}, now {b[i]!r}")
        else:
            diff = a != b
            n = int(np.count_nonzero(diff))
            lines.append(f"    {n} of {a.size} elements differ")
            if n:
                d = np.abs(a.astype(np.int64) - b.astype(np.int64))
                i = np.unravel_index(int(np.argmax(d)), a.shape)
                lines.append(f"    max abs difference {int(d[i])} at ({_coords(dn, i)}): "
                             f"baseline {a[i]!r}, now {b[i]!r}")
                if a.ndim and a.size < 10**8:  # how the flags moved, for the regime/validity codes
                    pairs, counts = np.unique(np.stack([a[diff], b[diff]]), axis=1, return_counts=True)
                    moves = ", ".join(f"{int(x)}->{int(y)}: {int(c)}" for (x, y), c in zip(pairs.T, counts))
                    lines.append(f"    baseline->now: {moves}")
        return "\n".join(lines)


def _json_diff(a, b, path, out):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in list(a) + [k for k in b if k not in a]:
            if k not in a or k not in b:
                out.append(f"    {path}.{k}: {'only now' if k not in a else 'only in the baseline'}")
            else:
                _json_diff(a[k], b[k], f"{path}.{k}", out)
        if list(a) != list(b) and set(a) == set(b):
            out.append(f"    {path}: key order changed")
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b)):
            _json_diff(x, y, f"{path}[{i}]", out)
    elif a != b or type(a) is not type(b):
        extra = ""
        if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
            d = abs(a - b)
            s = max(abs(a), abs(b))
            extra = f" (abs {d:.3g}, rel {d / s if s else 0:.3g})"
        out.append(f"    {path}: baseline {a!r}, now {b!r}{extra}")


def describe_json(base_file, new_file):
    with open(base_file) as fb, open(new_file) as fn:
        tb, tn = fb.read(), fn.read()
    try:
        jb, jn = json.loads(tb), json.loads(tn)
    except ValueError as e:
        return f"    not JSON: {e}"
    out = []
    _json_diff(jb, jn, "", out)
    if not out:
        out.append("    same values, different text (formatting or whitespace)")
    return "\n".join(out[:40]) + (f"\n    ... {len(out) - 40} more" if len(out) > 40 else "")


# ----------------------------------------------------------------------------------------

def compare(expected, actual):
    """(failures, notes): lists of (file, item-or-None, text)."""
    failures, notes = [], []
    exp, act = expected["arrays"], actual["arrays"]
    for f in sorted(set(exp) | set(act)):
        if f not in act:
            failures.append((f, None, "missing: the file was not written"))
            continue
        if f not in exp:
            failures.append((f, None, "extra: a file the baseline does not write"))
            continue
        e, a = exp[f], act[f]
        if isinstance(e, str) or isinstance(a, str):
            if e != a:
                failures.append((f, None, "differs (file bytes)"))
            continue
        for d in sorted(set(e) | set(a)):
            if d not in a:
                failures.append((f, d, "missing dataset"))
            elif d not in e:
                failures.append((f, d, "extra dataset"))
            elif e[d] != a[d]:
                failures.append((f, d, "differs"))
    ea, aa = expected.get("attributes", {}), actual.get("attributes", {})
    for f in sorted(set(ea) | set(aa)):
        e, a = ea.get(f, {}), aa.get(f, {})
        for k in sorted(set(e) | set(a)):
            if k not in a:
                notes.append((f, k, "attribute missing"))
            elif k not in e:
                notes.append((f, k, "attribute added"))
            elif e[k] != a[k]:
                notes.append((f, k, "attribute changed"))
    return failures, notes


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--expected", default=EXPECTED)
    parser.add_argument("--baseline-outputs", default=os.environ.get("PUNCHSWEEP_BASELINE_OUTPUTS"))
    parser.add_argument("--baseline-binary", default=os.environ.get("PUNCHSWEEP_BASELINE"))
    parser.add_argument("--keep", help="keep the outputs in this folder")
    parser.add_argument("--write-expected", action="store_true",
                        help="regenerate the expected hashes from $PUNCHSWEEP (numbers meant to change)")
    parser.add_argument("--revision", help="with --write-expected: the git revision the binary was built from")
    args = parser.parse_args()

    binary = os.environ.get("PUNCHSWEEP")
    if not binary:
        print("check.py: set PUNCHSWEEP to the punchsweep binary", file=sys.stderr)
        return 2
    binary = os.path.abspath(binary)

    work = tempfile.mkdtemp(prefix="punchsweep-regression.")
    out = args.keep or os.path.join(work, "outputs")
    if args.keep and os.path.isdir(out) and os.listdir(out):
        print(f"check.py: --keep {out} is not empty", file=sys.stderr)
        return 2
    keep_work = False
    try:
        print(f"regression outputs of {binary}")
        if not make_outputs(binary, out):
            keep_work = True
            return 1
        actual = array_hashes.hash_outputs(out)

        if args.write_expected:
            revision = args.revision
            if not revision:
                r = subprocess.run(["git", "-C", HERE, "rev-parse", "HEAD"], capture_output=True, text=True)
                revision = r.stdout.strip() or "unknown"
            actual = {"generated_with": {"revision": revision, "binary": binary,
                                         "how": "bash tests/regression/make_outputs.sh BINARY DIR; "
                                                "array_hashes.py DIR (via check.py --write-expected)"},
                      **actual}
            with open(args.expected, "w") as fh:
                json.dump(actual, fh, indent=1, sort_keys=True)
                fh.write("\n")
            n = sum(len(v) if isinstance(v, dict) else 1 for v in actual["arrays"].values())
            print(f"wrote {args.expected}: {n} hashes over {len(actual['arrays'])} files")
            return 0

        with open(args.expected) as fh:
            expected = json.load(fh)
        failures, notes = compare(expected, actual)

        for f, k, text in notes:
            print(f"note (not a failure): {f} {k}: {text}")
        if not failures:
            n = sum(len(v) if isinstance(v, dict) else 1 for v in actual["arrays"].values())
            print(f"PASS: all {n} datasets and point outputs in {len(actual['arrays'])} files equal the "
                  f"expected hashes (revision {expected.get('generated_with', {}).get('revision', '?')})")
            return 0

        keep_work = True
        base = args.baseline_outputs
        if not base and args.baseline_binary:
            base = os.path.join(work, "baseline")
            print(f"measuring the differences: baseline outputs of {args.baseline_binary}")
            if not make_outputs(os.path.abspath(args.baseline_binary), base):
                base = None
        if base:
            bh = array_hashes.hash_outputs(base)
            bad, _ = compare(expected, bh)
            if bad:
                print(f"warning: the baseline outputs in {base} do not match the expected hashes "
                      f"themselves ({len(bad)} differences); the measured differences are against them")
        for f, d, text in failures:
            print(f"FAIL: {f}{' ' + d if d else ''}: {text}")
            if base and text.startswith("differs"):
                bf, nf = os.path.join(base, f), os.path.join(out, f)
                if os.path.exists(bf):
                    print(describe_dataset(bf, nf, d) if d else describe_json(bf, nf))
        print(f"FAIL: {len(failures)} differences from {args.expected}")
        print(f"outputs kept in {out}" + (f", baseline outputs in {base}" if base else
                                          "; set PUNCHSWEEP_BASELINE=<baseline binary> to measure the differences"))
        return 1
    finally:
        if not keep_work:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
