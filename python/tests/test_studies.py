"""`contact2d.compare` and `contact2d.verify` against the CLI's `compare` and `verify` and
against closed forms.

compare: the interference fit (Lamé, `scenes/generic/interference_fit.toml`: 15 combinations of
0.03 s each) — the DataFrame's rows equal the CLI's compare.csv row for row: the texts exactly,
every value and error bit for bit (compare.csv writes Rust's shortest round-trip decimals, and
Python's `float` reads each back to the same double), all but the two wall-clock columns. The closed-form reference
p = E δ (b² − a²) / (2 a b²) is recomputed here, independently of the library.

verify: the interference_fit case (0.03 s; the whole gallery takes minutes, so the test runs one
case, as `contact2d verify --cases interference_fit` does): its references are the Lamé closed
forms computed here, and its measured values equal the CLI's table to the 6 decimals it prints.
"""

from __future__ import annotations

import csv
import math
import re
import tempfile
from pathlib import Path

import pytest
from conftest import ROOT, run_cli

import contact2d

FIT = ROOT / "scenes" / "generic" / "interference_fit.toml"
# Lamé (Timoshenko & Goodier §30): disk a = 500 mm in a ring b = 1000 mm, E = 2e5 MPa,
# radial interference δ = 0.6667 mm (the scene's comments and negative gap).
A, B, E, DELTA = 500.0, 1000.0, 2e5, 0.6667
P_LAME = E * DELTA * (B * B - A * A) / (2 * A * B * B)
HOOP_LAME = P_LAME * (B * B + A * A) / (B * B - A * A)
TIMES = ("time_s", "solve_time_s")


def cli_compare_csv(*args: str) -> tuple[list[str], list[dict[str, str]]]:
    """The header and rows (texts) of the CLI's compare.csv."""
    with tempfile.TemporaryDirectory() as tmp:
        done = run_cli("compare", *args, "--out", tmp)
        assert done.returncode == 0, done.stderr
        with open(Path(tmp) / "compare.csv", newline="") as f:
            reader = csv.DictReader(f)
            return list(reader.fieldnames or []), list(reader)


def same(got: object, text: str) -> bool:
    """Whether a DataFrame cell equals a compare.csv field: "" is a missing value, a number is
    compared as the double its text reads to (NaN with NaN), a text as text."""
    if text == "":
        return got is None or got == "" or (isinstance(got, float) and math.isnan(got))
    if isinstance(got, str):
        return got == text
    value = float(text)
    return (math.isnan(value) and math.isnan(float(got))) or float(got) == value  # type: ignore[arg-type]


def test_compare_equals_the_cli_compare_csv() -> None:
    reference = f"contacts.fit.max_pressure={P_LAME!r}"
    header, expected = cli_compare_csv(str(FIT), "--repeat", "1", "--reference", reference)
    got = contact2d.compare(contact2d.Scene.load(FIT), repeat=1, references={"contacts.fit.max_pressure": P_LAME})
    assert list(got.columns) == header
    assert len(got) == len(expected) == 15  # 5 algorithms × 3 pairings × 1 mesh
    for i, row in enumerate(expected):
        for column in header:
            if column not in TIMES:
                assert same(got[column].iloc[i], row[column]), (i, column, got[column].iloc[i], row[column])
    refs = got.attrs["reference"]
    assert refs["contacts.fit.max_pressure"]["value"] == P_LAME
    assert refs["contacts.fit.max_pressure"]["kind"] == "closed_form"
    assert refs["contacts.fit.max_pressure"]["deviation"] == "error"
    # energy has no closed form here: on one mesh it is a difference from the most accurate
    # method (segment to segment, active set), named as such.
    assert refs["energy"]["kind"] == "finest" and refs["energy"]["deviation"] == "difference"
    assert refs["energy"]["from"] == "active_set × segment_to_segment on (scene)"
    assert "difference_energy" in header
    # Every combination converges to the Lamé pressure within 0.5 % (verify's tolerance).
    converged = got[got.status == "converged"]
    assert len(converged) > 0
    assert (converged["error_contacts.fit.max_pressure"] < 5e-3).all()


def test_compare_of_a_scene_with_overrides_and_from_dict() -> None:
    # A from_dict scene has no file: compare reads its TOML text with the mesh made absolute.
    import tomllib

    table = tomllib.loads(FIT.read_text())
    scene = contact2d.Scene.from_dict(table, base_dir=FIT.parent).set("contact.fit.friction", 0.1)
    header, expected = cli_compare_csv(str(FIT), "--repeat", "1", "--set", "contact.fit.friction=0.1")
    got = contact2d.compare(scene, repeat=1)
    assert list(got.columns) == header
    assert "contacts.fit.tangential_force" in header  # μ > 0 adds it, as in the CLI
    for i, row in enumerate(expected):
        for column in ("algorithm", "pairing", "status", "contacts.fit.max_pressure", "energy"):
            assert same(got[column].iloc[i], row[column]), (i, column)


def test_compare_errors_carry_the_cli_message() -> None:
    with pytest.raises(ValueError, match="--time-limit"):
        contact2d.compare(contact2d.Scene.load(FIT), time_limit=0.0)
    with pytest.raises(ValueError, match="--reference"):
        contact2d.compare(contact2d.Scene.load(FIT), references={"contacts.fit.max_pressure": 0.0})
    with pytest.raises(contact2d.MeshError, match="no_such.msh"):
        contact2d.compare(contact2d.Scene.load(FIT), meshes=[ROOT / "no_such.msh"])


def test_verify_one_case_against_lame_and_the_cli_table() -> None:
    frame = contact2d.verify(["interference_fit"], root=ROOT)
    checks = frame[frame.reference.notna()]
    assert len(checks) == 3 and checks.passed.all()
    # The references are the closed forms (computed here), bit for bit: same formula, same order.
    assert list(checks.reference) == [P_LAME, HOOP_LAME, P_LAME]
    assert (checks.tolerance_kind == "relative").all() and (checks.tolerance == 0.005).all()
    for measured, reference, error in zip(checks.measured, checks.reference, checks.error, strict=True):
        assert error == abs(measured - reference) / abs(reference)
    # The CLI prints the same measured values (6 decimals).
    done = run_cli("verify", "--cases", "interference_fit")
    assert done.returncode == 0, done.stderr
    printed = [float(m) for m in re.findall(r"measured\s+(-?[0-9.]+)", done.stdout)]
    assert printed == [round(m, 6) for m in checks.measured]


def test_verify_refuses_an_unknown_case_and_level() -> None:
    with pytest.raises(contact2d.Contact2dError, match="no such case"):
        contact2d.verify(["no_such_case"], root=ROOT)
    with pytest.raises(ValueError, match="level"):
        contact2d.verify(["incline"], level="slow", root=ROOT)
