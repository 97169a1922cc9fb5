"""The tutorial's joint posed from Python (``python/examples/clamped_block_joint.py``, on the
committed ``meshes/generic/clamped_block.msh``; docs/tutorials/clamped_block.md), against the
block's statics and Coulomb's slip load (Meriam & Kraige, *Statics*, §6/2):

* N = P and R1 = F + S1 (S the side support's reaction, held in step 1 only) at every converged
  step, to 1e-8 of P: the pair forces sum to the loads to round-off;
* about the reference point (``about=``), the contact's moment on the base is M plus the side
  support's reaction moment, to 1e-8 of P × the block's width 2 (the moment balance of the
  issue, "1e-8 of the load");
* the run ends ``not_held`` with the last held pull factor λ_h in (λ* − Δλ, λ*], λ* = μP/F(1),
  Δλ the load step 0.1 (the slip load μN to within the step).
"""

from __future__ import annotations

import sys

from conftest import ROOT

sys.path.insert(0, str(ROOT / "python" / "examples"))

import clamped_block_joint as tutorial  # noqa: E402

P, M, PULL, MU, STEP, WIDTH = 1000.0, 100.0, 1000.0, 0.35, 0.1, 2.0


def test_the_joint_posed_from_python_follows_statics_and_slips_at_mu_n() -> None:
    result = tutorial.solve(clamp=P, moment=M, pull=PULL, mu=MU)
    data = result.json
    assert data["moment_centre"] == list(tutorial.CLAMP_AT)
    assert data["status"] == "not_held", data.get("failed_check")
    converged = [row for row in data["steps"] if row["status"] == "converged"]
    assert len(converged) == 4
    for row in converged:
        contact = row["contacts"]["joint"]
        side = row["reactions"].get("block_left", [None, None])[0] or 0.0
        side_moment = row["reaction_moments"].get("block_left", 0.0)
        pull = row["factors"].get("pull", 0.0) * PULL
        assert abs(contact["normal_force"] - P) <= 1e-8 * P
        assert abs(contact["resultant"][0] - (pull + side)) <= 1e-8 * P
        assert abs(contact["moment"] - (M + side_moment)) <= 1e-8 * P * WIDTH
    # The side support held in the clamp step only.
    assert converged[0]["reactions"]["block_left"][0] is not None
    assert all(row["reactions"]["block_left"] == [None, None] for row in data["steps"][1:])
    held = data["not_held"]["last_held_factors"]["pull"]
    slip = MU * P / PULL
    assert slip - STEP < held <= slip, (held, slip)
    assert data["not_held"]["contact"] == "joint"
