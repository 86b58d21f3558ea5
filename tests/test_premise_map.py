"""The premise map: where high yaw damping destabilises the carbody mode on low conicity and
low damping lets the bogies hunt on high conicity. These pin the map's sign changes, the
conclusions the study's documentation draws from it."""

import numpy as np
import pandas as pd
import pytest

import loco
from loco.studies import premise_map as pm

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
    # A few cells of the committed map recomputed (docs/screening, scripts/premise_map.py).
    from pathlib import Path

    committed = pd.read_csv(Path(__file__).parents[1] / "docs/screening/premise_map.csv")
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
        "docs/premise.md is out of date: run python scripts/premise_docs.py --write"
    )
