"""The parameter schema from Python: the one list of vehicle keys, ranges that contain the study
box, the docs page generated from it, and bad vehicle input refused by name."""

import re
from pathlib import Path
from types import ModuleType

import pytest

import loco
from loco.studies.parameters import STUDY_PARAMETERS
from script_modules import load_script

ROOT = Path(__file__).resolve().parents[2]


def _docs_script() -> ModuleType:
    return load_script("parameter_docs")


def test_the_schema_is_the_default_vehicles_key_list_with_values_inside_the_ranges() -> None:
    schema = loco.parameter_schema()
    params = loco.Locomotive.default().parameters()
    # The optional keys the default vehicle leaves to the model.
    assert [k for k, s in schema.items() if not s.optional] == sorted(params)
    assert [k for k, s in schema.items() if s.optional] == ["assessment.bogie_mass"]
    for key, spec in ((k, s) for k, s in schema.items() if not s.optional):
        assert spec.contains(params[key].value), key
        assert params[key].unit == spec.unit, key
        assert spec.kind in ("real", "count") and spec.affects and spec.why, key
        if spec.kind == "count":
            assert spec.min == int(spec.min) and spec.max <= 16, key
    assert not set(loco.retired_parameters()) & set(schema)


def test_the_study_box_is_inside_the_physical_ranges() -> None:
    schema = loco.parameter_schema()
    for p in STUDY_PARAMETERS:
        spec = schema[loco.vehicle.STUDY_PARAMETERS[p.name]]
        assert spec.min <= p.low_si and p.high_si <= spec.max, p.name


def test_the_docs_page_lists_exactly_the_schema_keys_and_is_current() -> None:
    docs = _docs_script()
    page = docs.PAGE.read_text(encoding="utf-8")
    generated = page[page.index(docs.BEGIN) : page.index(docs.END) + len(docs.END)]
    assert generated == docs.render(), "run python scripts/docs/parameter_docs.py --write"
    listed: list[str] = []
    section = ""
    for line in generated.splitlines():
        if m := re.match(r"### \[(\w+)\]", line):
            section = m.group(1)
        elif m := re.match(r"\| `(\w+)` \|", line):
            if section:
                listed.append(f"{section}.{m.group(1)}")
        elif line.startswith("### ") and not line.startswith("### ["):
            section = ""
    assert sorted(listed) == list(loco.parameter_schema())


def test_out_of_range_needs_the_explicit_allowance_in_the_file() -> None:
    base = loco.Locomotive.default()
    with pytest.raises(loco.ParameterRangeError, match=r"secondary\.yaw_damper_damping.*1e30.*3e6"):
        base.replace(C_sx=1e30)
    with pytest.raises(loco.ParameterError):  # the range error is a parameter error
        base.replace({"carbody.mass": 1e-30})
    text = 'allow_out_of_range = ["carbody.mass"]\n' + base.default_toml()
    heavy = loco.Locomotive(toml_text=text, origin="heavy.toml").replace({"carbody.mass": 150e3})
    assert heavy["carbody.mass"] == 150e3


@pytest.mark.parametrize("value", [2.5, 0.4, 1e12, 1e9, -1.0, float("nan")])
def test_counts_are_small_whole_numbers(value: float) -> None:
    with pytest.raises(loco.ParameterError, match=r"secondary\.lateral_dampers_per_bogie"):
        loco.Locomotive.default().replace({"secondary.lateral_dampers_per_bogie": value})


def test_file_units_are_converted_or_refused(tmp_path: Path) -> None:
    text = loco.Locomotive.default().default_toml()
    old = 'lateral_damper_damping = { value = 2.5e4, unit = "N·s/m"'
    assert old in text
    path = tmp_path / "v.toml"
    path.write_text(
        text.replace(old, 'lateral_damper_damping = { value = 25, unit = "kN·s/m"'),
        encoding="utf-8",
    )
    assert loco.Locomotive.from_toml(path)["C_sy"] == 25e3
    path.write_text(
        text.replace(old, 'lateral_damper_damping = { value = 2.5e4, unit = "kN/mm"'),
        encoding="utf-8",
    )
    with pytest.raises(loco.LocoError, match=r"secondary\.lateral_damper_damping.*kN/mm"):
        loco.Locomotive.from_toml(path)


def test_unknown_and_retired_keys_are_refused_with_the_reason(tmp_path: Path) -> None:
    text = loco.Locomotive.default().default_toml()
    path = tmp_path / "v.toml"
    path.write_text(text.replace("[carbody]\nmass =", "[carbody]\nmas ="), encoding="utf-8")
    with pytest.raises(loco.LocoError, match=r"carbody\.mas.*did you mean `carbody\.mass`"):
        loco.Locomotive.from_toml(path)
    with pytest.raises(loco.ParameterError, match=r"track\.gauge.*scenario"):
        loco.Locomotive.default().replace({"track.gauge": 1.5})
    reasons = loco.retired_parameters()
    assert "derived" in reasons["track.shear_modulus"]
