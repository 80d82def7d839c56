#!/usr/bin/env python3
"""The JSON Schema of summary.json (docs/schemas.md) against the summaries the program writes, with Debian's
python3-jsonschema.

    validate_summaries.py PLYIMPACT SOURCE_DIR SCRATCH_DIR

Checks that the schema the program generates (`plyimpact schema summary`) is the shipped
schemas/summary.schema.json; that the summary of every shipped example validates — the recorded ones of
tests/reference/examples/ (Examples/ExampleUnchanged keeps each equal to what the program writes for its
deck, less the program's name, version, deck path and wall time) and, whole, the summaries of a fresh run
of one example of each analysis (impact, static, modal, buckling, threshold with a criterion and with a
damage area); and that a misspelt key, a value of the wrong type and a key at the wrong level each fail.
"""
import copy
import json
import pathlib
import subprocess
import sys

from shipped_schema import shipped_validator

exe, root, scratch = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
validator = shipped_validator(exe, root, ["schema", "summary"], "summary.schema.json")

summaries = {f"reference {p.name}": json.loads(p.read_text())
             for p in sorted((root / "tests" / "reference" / "examples").glob("*.summary.json"))}
fresh = ["thesis-3.6-v268", "static-annex2-loads", "modal-annex2", "buckling-annex2",
         "thesis-4.3-threshold-0_2-90_2-0_2", "threshold-matrix-damage"]
for name in fresh:
    out = scratch / name
    run = subprocess.run([exe, str(root / "examples" / f"{name}.toml"), "-o", str(out), "--overwrite"],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"{name}: exit {run.returncode}\n{run.stderr}")
    if "summary.json:" in run.stderr:
        sys.exit(f"{name}: the program found a key outside its table:\n{run.stderr}")
    summaries[f"fresh run of {name}"] = json.loads((out / "summary.json").read_text())
analyses = sorted({s["analysis"] for s in summaries.values()})

failed = []
for name, summary in summaries.items():
    for error in validator.iter_errors(summary):
        failed.append(f"{name}: {'/'.join(map(str, error.absolute_path))}: {error.message}")
if failed:
    sys.exit("summaries that do not validate:\n" + "\n".join(failed))
print(f"{len(summaries)} summaries valid ({len(fresh)} fresh runs; analyses: {', '.join(analyses)})")

impact = summaries["fresh run of thesis-3.6-v268"]
slips = {
    "a misspelt key": lambda s: s.update(peak_forse=s.pop("peak_force")),
    "a wrong type": lambda s: s.update(steps="2000"),
    "a key at the wrong level": lambda s: s["mesh"].update(peak_force=1.0),
    "a misspelt key in a list": lambda s: s["episodes"][0].update(pek_force=1.0),
}
for what, slip in slips.items():
    summary = copy.deepcopy(impact)
    slip(summary)
    errors = list(validator.iter_errors(summary))
    if not errors:
        sys.exit(f"{what} validated")
    print(f"{what} refused: {errors[0].message}")
