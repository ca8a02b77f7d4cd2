#!/usr/bin/env python3
"""Validates JSON Lines (cloudshape-recognize / -echo output) against a JSON Schema file.

Uses the jsonschema library (Debian python3-jsonschema), independent of the project's own
C++ checker. Exit status 0 when there is at least one line and every line conforms.
"""
import json
import sys

import jsonschema


def main(argv):
    if len(argv) < 2:
        print("usage: validate_results.py SCHEMA [JSONL...] (stdin without files)", file=sys.stderr)
        return 2
    with open(argv[1], encoding="utf-8") as f:
        schema = json.load(f)
    jsonschema.Draft7Validator.check_schema(schema)
    validator = jsonschema.Draft7Validator(schema)
    streams = [open(p, encoding="utf-8") for p in argv[2:]] or [sys.stdin]
    lines = bad = 0
    for stream in streams:
        for number, line in enumerate(stream, 1):
            if not line.strip():
                continue
            lines += 1
            try:
                document = json.loads(line)
            except json.JSONDecodeError as e:
                print(f"{stream.name}:{number}: not JSON: {e}", file=sys.stderr)
                bad += 1
                continue
            errors = sorted(validator.iter_errors(document), key=lambda e: list(e.absolute_path))
            for e in errors:
                where = "/".join(str(p) for p in e.absolute_path) or "(top level)"
                print(f"{stream.name}:{number}: {document.get('source', '?')}: {where}: {e.message}",
                      file=sys.stderr)
            bad += bool(errors)
    print(f"{lines} result lines, {bad} not conforming to {argv[1]}")
    return 0 if lines > 0 and bad == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
