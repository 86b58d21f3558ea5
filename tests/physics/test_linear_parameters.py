"""The linear contact parameters from Python (λ, ε, σ, gravitational stiffness), the contact
pairs' table and its generated page."""

from __future__ import annotations

import csv
import math
from pathlib import Path
from types import ModuleType

import pytest

import loco
from loco import contact, contact_pairs, profiles
from loco._loco import conical_profiles
from loco.cli import main
from script_modules import load_script

ROOT = Path(__file__).resolve().parents[2]


def _docs_script() -> ModuleType:
    return load_script("contact_pairs_docs")


@pytest.mark.parametrize("lam", [0.02, 0.04, 0.15])
def test_cone_on_knife_edge_has_no_contact_angle_parameter_and_wickens_roll(lam: float) -> None:
    wheel, rail = conical_profiles(lam)
    p = contact.linear_parameters(wheel, rail, axle_load=2.0e5)
    assert abs(p.contact_angle_parameter) < 1e-4
    # Roll of a cone on knife edges (the crown's 10 mm radius is below the contact, so it
    # only deepens the contact): φ' = tan δ0 / (l0 − r0 tan δ0), σ = l0 φ'.
    t = math.tan(p.contact_angle)
    assert p.contact_angle == pytest.approx(math.atan(lam), abs=1e-6)
    l0, r0 = p.half_contact_spacing, p.rolling_radius
    assert p.roll_parameter == pytest.approx(l0 * t / (l0 - r0 * t), rel=1e-4)
    assert p.gravitational_stiffness == pytest.approx(2.0e5 * p.gravitational_stiffness_per_load)
    assert p.gravitational_stiffness_per_load > 0.0


def test_bad_amplitude_and_axle_load_are_refused_by_name() -> None:
    wheel, rail = profiles.builtin("jm3-new"), profiles.builtin("cn60")
    with pytest.raises(loco.ParameterError, match="amplitude"):
        contact.linear_parameters(wheel, rail, amplitude=-1e-3)
    with pytest.raises(loco.ParameterError, match="axle_load"):
        contact.linear_parameters(wheel, rail, axle_load=0.0)
    assert math.isnan(contact.linear_parameters(wheel, rail).gravitational_stiffness)


def test_axle_load_is_the_locomotives_weight_over_four_wheelsets() -> None:
    vehicle = loco.Locomotive.default()
    assert contact.axle_load() == pytest.approx(
        vehicle.total_mass() * vehicle["track.gravity"] / 4.0
    )


def test_pairs_table_gives_what_the_model_measures() -> None:
    rows = {(r["wheel"], r["rail"], r["cant"]): r for r in contact_pairs.pair_rows()}
    assert len(rows) == len(contact_pairs.PAIRS)
    s_low = rows["jm3-thin-flange", "cn60", 40]
    # The S_low pair: its rolled λ near its EN 15302 conicity, the conformal tread's ε far from
    # a cone's 0.
    assert s_low["lambda"] == pytest.approx(s_low["tan_gamma_e_3mm"], abs=0.005)
    assert s_low["epsilon"] > 2.0
    # Rails at 1:20 lower the new wheel's conicity to the S_low range; the thin flange there
    # has no centred running position by EN 15302.
    new_20 = rows["jm3-new", "cn60", 20]
    assert 0.02 < new_20["tan_gamma_e_3mm"] < 0.06
    thin_20 = rows["jm3-thin-flange", "cn60", 20]
    assert math.isnan(thin_20["tan_gamma_e_3mm"]) and "EN 15302" in thin_20["note"]
    assert abs(thin_20["lambda"]) < 0.005


def test_committed_contact_pairs_page_is_the_generated_one() -> None:
    docs = _docs_script()
    assert docs.PAGE.read_text(encoding="utf-8") == docs.render(), (
        "run python scripts/docs/contact_pairs_docs.py --write"
    )


def test_contact_report_writes_the_pairs_table(tmp_path: Path) -> None:
    out = tmp_path / "report"
    assert main(["contact-report", "--out", str(out)]) == 0
    with (out / "contact_pairs.csv").open() as f:
        rows = list(csv.DictReader(f))
    assert [(r["wheel"], r["rail"], int(r["cant"])) for r in rows] == [
        (p.wheel, p.rail, p.cant) for p in contact_pairs.PAIRS
    ]
    assert "cn60-gauge-ground" in (out / "contact_pairs.md").read_text()
