"""The premise map: where high yaw damping destabilises the carbody mode on low conicity and
low damping lets the bogies hunt on high conicity. These pin the map's sign changes, the
conclusions the study's documentation draws from it."""

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import loco
from loco.studies import premise_modes as pm

PRESETS = (200e3, 800e3)


@pytest.fixture(scope="module")
def cones() -> pd.DataFrame:
    return pm.premise_map(
        conicities=(0.01, 0.04), dampings=PRESETS, families=("knife-edge cone",), progress=False
    )


def cell(cells: pd.DataFrame, pair: str) -> pd.Series:
    row = cells[cells["pair"] == pair]
    assert len(row) == 1, pair
    return row.iloc[0]


def test_the_textbook_cone_shows_the_premise_at_conicity_0_04(cones: pd.DataFrame) -> None:
    cells = pm.premise_cells(cones)
    c = cell(cells, "cone 0.04")
    assert c["premise"], c.to_dict()
    # Below it, at 0.01, the carbody mode is unstable with either damper: no damper helps.
    low = cell(cells, "cone 0.01")
    assert low["carbody_zeta_low"] < 0 and low["carbody_zeta_high"] < 0


@pytest.mark.slow
def test_real_pairs_the_default_vehicle_holds_new_wheels_on_1_in_20_show_the_premise() -> None:
    result = pm.premise_map(dampings=PRESETS, families=("pair",), progress=False)
    cells = pm.premise_cells(result)
    # The study's S_low pair: high damping takes most of the carbody mode's damping, but both
    # dampers keep it stable, so the premise does not hold on the default vehicle.
    s_low = cell(cells, "jm3-thin-flange on cn60 1:40")
    assert 0 < s_low["carbody_zeta_high"] < 0.5 * s_low["carbody_zeta_low"]
    assert not s_low["premise"]
    # The field problem's larger rail cant with newly turned wheels: the premise holds.
    assert cell(cells, "jm3-new on cn60 1:20")["premise"]
    # Worn wheels: the bogie mode hunts with YD1 and is stable with YD2 (the reverse).
    assert cell(cells, "jm3-worn on cn60 1:40")["reverse"]
    assert set(cells.loc[cells["premise"], "pair"]) == {"jm3-new on cn60 1:20"}


def test_the_map_is_the_same_through_a_process_pool(cones: pd.DataFrame) -> None:
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(max_workers=2) as pool:
        pooled = pm.premise_map(
            conicities=(0.01, 0.04),
            dampings=PRESETS,
            families=("knife-edge cone",),
            executor=pool,
            progress=False,
        )
    pd.testing.assert_frame_equal(pooled, cones)


def test_bad_families_and_pairs_are_refused() -> None:
    with pytest.raises(loco.ParameterError, match="unknown family `cones`"):
        pm.premise_map(families=("cones",), progress=False)
    with pytest.raises(loco.ParameterError, match="unknown pair"):
        pm.speed_sweep(cases=(("pair", "jm3 on uic60"),), progress=False)


def test_the_committed_map_is_what_the_model_gives_now() -> None:
    # A few cells of the committed map recomputed (docs/screening, scripts/docs/premise_modes.py).
    from pathlib import Path

    committed = pd.read_csv(Path(__file__).parents[2] / "docs/screening/premise_map.csv")
    fresh = pm.premise_map(
        conicities=(0.03,), dampings=(500e3,), families=("cone on CN60",), progress=False
    )
    merged = fresh.merge(committed, on=["family", "pair", "damping", "mode"], suffixes=("", "_c"))
    assert len(merged) == 2
    np.testing.assert_allclose(merged["damping_ratio"], merged["damping_ratio_c"], rtol=1e-5)
    np.testing.assert_allclose(merged["frequency"], merged["frequency_c"], rtol=1e-5)


def test_the_premise_page_is_generated_from_the_committed_results() -> None:
    from script_modules import load_script

    docs = load_script("premise_docs")
    assert docs.PAGE.read_text(encoding="utf-8") == docs.render(), (
        "docs/premise.md is out of date: run python scripts/docs/premise_docs.py --write"
    )


@pytest.mark.slow
def test_the_premise_case_is_new_wheels_on_rails_inclined_1_in_20() -> None:
    from loco.contact_pairs import ContactPair
    from loco.studies import premise_case

    table = premise_case.candidates()
    assert premise_case.choose_pair(table) == ContactPair("jm3-new", "cn60", 20)
    # No pair qualifies: no premise case.
    assert premise_case.choose_pair(table.assign(premise=False)) is None


def test_the_premise_section_reads_the_rule_from_the_tracks(tmp_path: Path) -> None:
    from loco.studies import premise_report

    rows = []
    # S_low is judged by the A_yc PSD peak, S_high by the A_yb peak: each scenario's rows
    # carry one value in both columns.
    for scenario, values in (
        ("S_low", {"YD1": 0.01, "YD2": 0.03}),
        ("S_high", {"YD1": 6.0, "YD2": 2.0}),
    ):
        for damper, v in values.items():
            for track in range(3):
                rows.append(
                    {
                        "scenario": scenario,
                        "damper": damper,
                        "track": track,
                        "status": 0,
                        "psd_peak": v,
                        "ayb_peak_lp": v,
                        "wy_max": 2.0,
                    }
                )
    path = tmp_path / "fsd_tracks.csv"
    pd.DataFrame(rows).to_csv(path, index=False)
    assert premise_report.psd_ratios(pd.read_csv(path)) == pytest.approx(
        {"S_low": 3.0, "S_high": 3.0}
    )
    text = "\n".join(premise_report.premise_section(path, None))
    assert "On the default vehicle: yes" in text
    assert "docs/premise.md" in text


def test_the_committed_plausible_locomotives_are_what_the_model_gives_now() -> None:
    # docs/screening/plausible.csv (scripts/docs/premise_probability.py): one locomotive's S_low
    # runs re-simulated, and the committed shares are the summary of the committed table.
    import json

    from loco.studies import premise_probability as pp

    results = Path(__file__).parents[2] / "docs" / "screening"
    meta = json.loads((results / "plausible.json").read_text(encoding="utf-8"))
    frame = pd.read_csv(results / "plausible.csv")
    inputs, pairs = pp.sample_locomotives(meta["n"], meta["seed"])
    assert pairs == list(frame["s_low_pair"])
    np.testing.assert_allclose(frame[list(inputs.columns)], inputs, rtol=1e-5)
    i = 0
    pair = next(p for p in pp.S_LOW_PAIRS if p.label == pairs[i])
    for damper in ("YD1", "YD2"):
        values = []
        for track in range(meta["n_tracks"]):
            scenario = loco.Scenario(
                wheel=pair.wheel,
                rail=pair.rail,
                rail_inclination=pair.inclination,
                speed=meta["speed_kmh"] / 3.6,
                distance=meta["distance_m"],
                lead_in=meta["lead_in_m"],
                seed=track,
                yaw_damper=damper,
            )
            batch = loco.run_batch(
                inputs.to_numpy()[i : i + 1], list(inputs.columns), scenario=scenario,
                progress=False,
            )  # fmt: skip
            values.append(batch.metric(pp.JUDGE["S_low"])[0])
        assert np.mean(values) == pytest.approx(frame.loc[i, f"S_low {damper}"], rel=1e-4)
    summary = pp.summarise(pp.from_frame(frame))
    committed = pd.read_csv(results / "plausible_fraction.csv")
    np.testing.assert_allclose(summary["fraction"]["k"], committed["k"])
    np.testing.assert_allclose(summary["fraction"]["fraction"], committed["fraction"], rtol=1e-3)
