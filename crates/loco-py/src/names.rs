//! The core's names as Python constants: `Metric` (one class attribute per run metric, generated
//! from `loco_core::metric_table!`, so a metric is named in the core only), `ChannelKind` (the
//! families of output channels, from `loco_core::channel_kind_table!`), the metric table itself (for the docs) and the channel table of
//! a built vehicle (name, unit, kind per channel, from its `ChannelSet`).

use crate::errors::to_py_err;
use crate::vehicle_handle::PyVehicle;
use loco_core::metrics::METRIC_TABLE;
use loco_core::vehicle::output::channel_set::{ChannelKind, ChannelSet};
use pyo3::prelude::*;

/// The run metric names as constants (`Metric.WY_MAX == "wy_max"`), in column order.
#[pyclass(name = "Metric", module = "loco._loco", frozen)]
pub struct PyMetric;

macro_rules! metric_constants {
    ($( $constant:ident $field:ident : $ty:ty, $unit:literal, $doc:literal; )*) => {
        #[pymethods]
        impl PyMetric {
            $(
                #[classattr]
                const $constant: &'static str = loco_core::metrics::metric::$constant;
            )*
        }
    };
}
loco_core::metric_table!(metric_constants);

/// The kinds of output channels as constants (`ChannelKind.DAMPER_VALVE == "damper_valve"`).
#[pyclass(name = "ChannelKind", module = "loco._loco", frozen)]
pub struct PyChannelKind;

macro_rules! channel_kind_constants {
    ($( $constant:ident $variant:ident $name:literal, $doc:literal; )*) => {
        #[pymethods]
        impl PyChannelKind {
            $(
                #[classattr]
                const $constant: &'static str = ChannelKind::$variant.name();
            )*
        }
    };
}
loco_core::channel_kind_table!(channel_kind_constants);

/// Every channel kind's name, in the core's order.
#[pyfunction]
fn channel_kinds() -> Vec<&'static str> {
    ChannelKind::ALL.iter().map(|k| k.name()).collect()
}

/// The run metrics as `(name, unit, description, is_flag)` rows, in column order.
#[pyfunction]
fn metric_table() -> Vec<(&'static str, &'static str, &'static str, bool)> {
    METRIC_TABLE
        .iter()
        .map(|m| (m.name, m.unit, m.description, m.flag))
        .collect()
}

/// The output channels of a run of `vehicle` as `(name, unit, kind)` rows, in recording order.
#[pyfunction]
fn channel_table(vehicle: &PyVehicle) -> PyResult<Vec<(String, &'static str, &'static str)>> {
    let set = ChannelSet::new(&vehicle.structure).map_err(to_py_err)?;
    Ok(set
        .channels()
        .iter()
        .map(|c| (c.name.clone(), c.unit, c.kind().name()))
        .collect())
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyMetric>()?;
    m.add_class::<PyChannelKind>()?;
    m.add_function(wrap_pyfunction!(channel_kinds, m)?)?;
    m.add_function(wrap_pyfunction!(metric_table, m)?)?;
    m.add_function(wrap_pyfunction!(channel_table, m)?)?;
    Ok(())
}
