"""A vehicle's hash is that of its resolved parameters: how its file is written (comments,
sources, the units a value is stated in) does not change a stage's or a campaign's hash, so an
edit that changes no value reruns nothing; any value, in the file or as an override, does."""

from __future__ import annotations

import numpy as np

import loco
from loco.campaign import campaign_inputs
from loco.studies.stages import encode

KEY = "traction_motor.suspension_damping_x"


def _default_text() -> str:
    return loco.Locomotive.default().default_toml()


def _edited_text() -> str:
    """The default file rewritten without changing a value: a comment, a source, a unit."""
    text = _default_text()
    line = next(x for x in text.splitlines() if x.startswith("suspension_damping_x ="))
    restated = (
        'suspension_damping_x = { value = 25.0, unit = "kN·s/m", '
        'source = "the same value in kN·s/m" }'
    )
    assert line in text
    return "# an engineer's note\n" + text.replace(line, restated)


def test_a_file_written_differently_with_the_same_values_has_the_same_hash() -> None:
    default = loco.Locomotive.default()
    same_text = loco.Locomotive(toml_text=_default_text(), origin="copy.toml")
    edited = loco.Locomotive(toml_text=_edited_text(), origin="edited.toml")
    assert edited[KEY] == default[KEY]
    assert default.parameters_sha256() == same_text.parameters_sha256()
    assert edited.parameters_sha256() == default.parameters_sha256()
    assert encode(edited) == encode(default)
    x = np.zeros((1, 1))
    scenario = loco.Scenario(name="S_high")
    assert campaign_inputs(x, ["K_px"], edited, scenario, 0) == campaign_inputs(
        x, ["K_px"], default, scenario, 0
    )


def test_any_value_changes_the_hash() -> None:
    default = loco.Locomotive.default()
    changed = loco.Locomotive(
        toml_text=_default_text().replace(
            "suspension_damping_x = { value = 2.5e4", "suspension_damping_x = { value = 2.6e4"
        )
    )
    assert changed[KEY] == 2.6e4
    assert changed.parameters_sha256() != default.parameters_sha256()
    # An override is a value too, and one equal to the file's value changes nothing.
    assert default.replace({KEY: 2.6e4}).parameters_sha256() == changed.parameters_sha256()
    assert default.replace({KEY: 2.5e4}).parameters_sha256() == default.parameters_sha256()
    x = np.zeros((1, 1))
    scenario = loco.Scenario(name="S_high")
    assert campaign_inputs(x, ["K_px"], changed, scenario, 0) != campaign_inputs(
        x, ["K_px"], default, scenario, 0
    )
