#!/usr/bin/env python3
"""The deck's JSON Schema (docs/schemas.md) against the decks we ship, with Debian's python3-jsonschema.

    validate_decks.py PLYIMPACT SOURCE_DIR

Checks that the schema the program generates (`plyimpact schema`) is the shipped schemas/deck.schema.json;
that every shipped example, every benchmark deck and the starting deck of `plyimpact init` validate; and
that a misspelt key, a misspelt table and a value of the wrong type each fail validation, as the parser
refuses them.
"""
import pathlib
import subprocess
import sys
import tomllib

from shipped_schema import shipped_validator

exe, root = sys.argv[1], pathlib.Path(sys.argv[2])
validator = shipped_validator(exe, root, ["schema"], "deck.schema.json")

decks = sorted(root.glob("examples/*.toml")) + sorted(root.glob("bench/decks/*.toml"))
texts = {str(d.relative_to(root)): d.read_text() for d in decks}
texts["plyimpact init"] = subprocess.run([exe, "init"], check=True, capture_output=True, text=True).stdout
failed = []
for name, text in texts.items():
    for error in validator.iter_errors(tomllib.loads(text)):
        failed.append(f"{name}: {'/'.join(map(str, error.absolute_path))}: {error.message}")
if failed:
    sys.exit("decks that do not validate:\n" + "\n".join(failed))
print(f"{len(texts)} decks valid")

slips = {
    "a misspelt key": lambda d: d["impactor"].update(velocty=d["impactor"].pop("velocity")),
    "a misspelt table": lambda d: d.update(impacter=d.pop("impactor")),
    "a wrong type": lambda d: d["mesh"].update(nx="15"),
}
for what, slip in slips.items():
    deck = tomllib.loads(texts["examples/thesis-3.6-v268.toml"])
    slip(deck)
    errors = list(validator.iter_errors(deck))
    if not errors:
        sys.exit(f"{what} validated")
    print(f"{what} refused: {errors[0].message}")
