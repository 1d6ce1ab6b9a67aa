"""The cells of a `raylab bench` folder, one record per cell, for the scripts that draw from it
(bench_charts.py, study_report.py, thesis_table.py).

A sweep measures every cell in rounds (--rounds): results.jsonl holds one record per cell and round, and the
bench writes cells.jsonl at the end with one record per cell, its rounds made one (app/bench/bench_rounds.h: times
are medians over the rounds, and their spreads, {median, min, max, q1, q3}, are over the rounds; min to q3
null with one round). A folder from before rounds has no cells.jsonl: its results.jsonl holds one record per
cell, read as one round each.
"""
import json
import os


class NotABenchFolder(Exception):
    pass


def cells_path(folder):
    """cells.jsonl where the sweep wrote it, else results.jsonl (a folder from before rounds)."""
    cells = os.path.join(folder, "cells.jsonl")
    if os.path.isfile(cells):
        return cells
    results = os.path.join(folder, "results.jsonl")
    if os.path.isfile(results):
        return results
    raise NotABenchFolder(f"{folder} has no cells.jsonl or results.jsonl (not a raylab bench folder?)")


def load_cells(folder):
    """Every cell's record, in file order; NotABenchFolder or ValueError (naming the file and line)."""
    path = cells_path(folder)
    cells = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            if not line.strip():
                continue
            try:
                cells.append(json.loads(line))
            except json.JSONDecodeError as e:
                raise ValueError(f"{path}:{number}: not a JSON line ({e.msg})")
    if path.endswith("results.jsonl") and any(c.get("round", 0) > 0 for c in cells):
        # Rounds of one cell are not cells: only the bench makes them one, when the sweep ends.
        raise NotABenchFolder(f"{folder} has no cells.jsonl: its sweep did not finish "
                              f"(raylab bench --resume {folder} finishes it)")
    return cells


def spread(value):
    """(median, min, max) of a spread object; min and max None where not measured (one round)."""
    if isinstance(value, dict):
        def number(key):
            v = value.get(key)
            return float(v) if isinstance(v, (int, float)) else None
        return number("median"), number("min"), number("max")
    if isinstance(value, (int, float)):
        return float(value), None, None
    return None, None, None


def rounds_of(cell):
    return int(cell.get("rounds", 1))


def distinguishable(a, b):
    """Whether two (median, min, max) spreads do not overlap: only then is one faster than the other. With a
    spread not measured (one round) nothing is distinguishable. The bench's own rule: app/bench/bench_spread.h."""
    if None in (a[1], a[2], b[1], b[2]):
        return False
    return a[2] < b[1] or b[2] < a[1]
