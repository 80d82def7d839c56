"""What both schema tests check first: the schema the program generates is the one we ship, and it is a
valid draft-07 schema. Returns its validator."""
import json
import pathlib
import subprocess
import sys

import jsonschema


def shipped_validator(exe: str, root: pathlib.Path, command: list[str],
                      file: str) -> jsonschema.Draft7Validator:
    """`plyimpact <command>` against schemas/<file>; exits naming the regeneration where they differ."""
    generated = json.loads(subprocess.run([exe, *command], check=True, capture_output=True, text=True).stdout)
    shipped = json.loads((root / "schemas" / file).read_text())
    if generated != shipped:
        sys.exit(f"schemas/{file} is not what `plyimpact {' '.join(command)}` writes: regenerate it "
                 f"(build/release/plyimpact {' '.join(command)} > schemas/{file})")
    jsonschema.Draft7Validator.check_schema(shipped)
    return jsonschema.Draft7Validator(shipped)
