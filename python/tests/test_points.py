"""Reference points from a dict: the keys `[[point]]`, `[[fix]] point` and `[[load]] point` go
through the same TOML as a scene file. The pad of `pad_on_base.toml` held by a kinematic point
fixed at (0, -0.001), rotation 0, is the same discrete problem as its `pad_top` fix: the point's
reaction is that group's, and a distributing point coupled to the clamped `base_bottom` reports
the opposite force (equilibrium, to 1e-8 of the force)."""

from __future__ import annotations

import tomllib

from conftest import ROOT, cli_json

import contact2d

PAD = ROOT / "scenes" / "generic" / "pad_on_base.toml"


def test_a_kinematic_point_poses_the_group_fix_and_its_reaction_balances() -> None:
    expected = cli_json(PAD)
    with PAD.open("rb") as f:
        table = tomllib.load(f)
    table["fix"] = [f for f in table["fix"] if f["group"] != "pad_top"]
    table["point"] = [
        {"name": "cap", "at": [2.5, 1.2], "group": "pad_top", "coupling": "kinematic"},
        {"name": "anchor", "at": [2.5, 0.0], "group": "base_bottom", "coupling": "distributing"},
    ]
    table["fix"].append({"point": "cap", "u1": 0.0, "u2": -0.001, "rotation": 0.0})
    result = contact2d.solve(contact2d.Scene.from_dict(table, base_dir=PAD.parent)).json
    cap, anchor = result["points"]["cap"], result["points"]["anchor"]
    force = abs(expected["reactions"]["pad_top"][1])
    for c in range(2):
        assert abs(cap["reaction"][c] - expected["reactions"]["pad_top"][c]) <= 1e-8 * force
        assert abs(cap["reaction"][c] + anchor["reaction"][c]) <= 1e-8 * force
    assert abs(cap["displacement"][0]) < 1e-15 and abs(cap["displacement"][1] + 0.001) < 1e-15
    assert abs(cap["rotation"]) < 1e-15
    assert result["steps"][-1]["points"]["cap"] == cap
