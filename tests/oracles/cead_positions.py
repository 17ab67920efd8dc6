"""A second reading of the dry run's positions: `sinuprep run` without a
machine (the programmed positions through the programmable frames) against
CEAD's interpreter (PyPI `nc-gcode-interpreter`), program by program: the
sequence of distinct consecutive (X, Y, Z) positions of each.

    python3 -m venv venv && venv/bin/pip install nc-gcode-interpreter
    cargo build && venv/bin/python tests/oracles/cead_positions.py \
        target/debug/sinuprep ../shared/corpus/cead-examples/*.mpf

Not run by CI (it needs the package from PyPI); docs/design.md gives the
figures and where the two differ.
"""
import json, subprocess, sys, math
import nc_gcode_interpreter as cead

def cead_positions(text):
    df, state = cead.nc_to_dataframe(text)
    cols = [c for c in ("X", "Y", "Z") if c in df.columns]
    rows = df.select(cols).to_dicts()
    out, last = [], {}
    for r in rows:
        for c in cols:
            if r[c] is not None and not (isinstance(r[c], float) and math.isnan(r[c])):
                last[c] = r[c]
        p = tuple(last.get(c) for c in ("X", "Y", "Z"))
        if not out or out[-1] != p:
            out.append(p)
    return out

def ours(path):
    res = subprocess.run([sys.argv[1], "run", "--format", "json", "--blocks", path], capture_output=True, text=True)
    doc = json.loads(res.stdout)
    out = []
    for b in doc["blocks"]:
        m = b["mcs"]
        p = tuple(m.get(c) for c in ("X", "Y", "Z"))
        if not out or out[-1] != p:
            out.append(p)
    return out, doc["unknown"]

def same(a, b):
    if len(a) != len(b): return False
    for p, q in zip(a, b):
        for x, y in zip(p, q):
            if (x is None) != (y is None): return False
            if x is not None and abs(x - y) > 1e-6: return False
    return True

agree = differ = failed = 0
for path in sys.argv[2:]:
    text = open(path, encoding="latin-1").read()
    try:
        theirs = cead_positions(text)
    except BaseException as e:
        failed += 1
        print(f"CEAD could not run {path}: {str(e)[:100]}")
        continue
    mine, unknown = ours(path)
    # Our first positions may be partial (unknown axes) where CEAD starts at 0.
    if same(mine, theirs):
        agree += 1
    else:
        differ += 1
        print(f"DIFFER {path}: ours {mine[:6]} ... ({len(mine)}) theirs {theirs[:6]} ... ({len(theirs)}); unknown: {[u['why'][:60] for u in unknown][:3]}")
print(f"agree {agree}, differ {differ}, CEAD failed {failed}")
