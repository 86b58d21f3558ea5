//! The native vehicle handle: a parameter file parsed once, its overrides applied and the 25-body
//! model built once, shared (`Arc`) by every binding that takes a vehicle. `loco.Locomotive`
//! wraps it; `replace` returns a new handle; pickling rebuilds it from the file text and the
//! overrides (the Dask executor sends a vehicle to its workers that way).

use crate::errors::{run_detached, to_py_err};
use loco_core::vehicle::model::layout::N_DOF;
use loco_core::vehicle::model::structure::VehicleStructure;
use loco_core::vehicle::params::parameter_schema::spec;
use loco_core::vehicle::params::parameters::{resolve_name, ParameterSet};
use loco_core::LocoError;
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray2};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use std::collections::BTreeMap;
use std::sync::Arc;

/// A built vehicle: the parameter file (`toml_text`, None for the embedded default; `origin`
/// names it in errors), the overrides (SI, by file key or study alias) and the model built from
/// them. Immutable; cheap to share.
#[pyclass(name = "Vehicle", module = "loco._loco", frozen)]
pub struct PyVehicle {
    /// The file text as given (None: the embedded default), kept for pickling.
    toml_text: Option<Arc<str>>,
    origin: String,
    /// The file's parameters before the overrides, parsed once (`replace` starts from them).
    file: Arc<ParameterSet>,
    overrides: BTreeMap<String, f64>,
    /// The built model; its `parameters` are the file's with the overrides applied.
    pub structure: Arc<VehicleStructure>,
}

/// The file's parameters with `overrides` applied, and the model built from them.
fn build(
    file: &ParameterSet,
    overrides: &BTreeMap<String, f64>,
) -> loco_core::Result<VehicleStructure> {
    let mut set = file.clone();
    for (name, value) in overrides {
        set.set(name, *value)?;
    }
    VehicleStructure::new(set)
}

impl PyVehicle {
    /// The parameters of the built model (the file's with the overrides applied).
    pub fn parameters(&self) -> &ParameterSet {
        &self.structure.parameters
    }
}

#[pymethods]
impl PyVehicle {
    /// Parses the file (None: the embedded default), applies the overrides and builds the
    /// vehicle; a non-physical or unknown parameter raises `ParameterError` naming it.
    #[new]
    #[pyo3(signature = (toml_text=None, origin="<vehicle>".to_string(), overrides=BTreeMap::new()))]
    fn new(
        py: Python<'_>,
        toml_text: Option<String>,
        origin: String,
        overrides: BTreeMap<String, f64>,
    ) -> PyResult<Self> {
        let toml_text: Option<Arc<str>> = toml_text.map(Arc::from);
        let text = toml_text.clone();
        let (file, structure, origin, overrides) = run_detached(py, move || {
            let file = match text.as_deref() {
                Some(text) => ParameterSet::from_toml_str(text, &origin)?,
                None => ParameterSet::default_vehicle(),
            };
            let structure = build(&file, &overrides)?;
            Ok((file, structure, origin, overrides))
        })?;
        Ok(Self {
            toml_text,
            origin,
            file: Arc::new(file),
            overrides,
            structure: Arc::new(structure),
        })
    }

    /// A new vehicle with `overrides` merged over these ones (the file is not parsed again).
    fn replace(&self, py: Python<'_>, overrides: BTreeMap<String, f64>) -> PyResult<Self> {
        let mut merged = self.overrides.clone();
        merged.extend(overrides);
        let file = Arc::clone(&self.file);
        let (structure, merged) = run_detached(py, move || {
            let structure = build(&file, &merged)?;
            Ok((structure, merged))
        })?;
        Ok(Self {
            toml_text: self.toml_text.clone(),
            origin: self.origin.clone(),
            file: Arc::clone(&self.file),
            overrides: merged,
            structure: Arc::new(structure),
        })
    }

    /// The parameter file's text (None: the embedded default).
    #[getter]
    fn toml_text(&self) -> Option<&str> {
        self.toml_text.as_deref()
    }

    /// The name of the parameter file in error messages.
    #[getter]
    fn origin(&self) -> &str {
        &self.origin
    }

    /// The overrides (SI) by the names they were given with.
    #[getter]
    fn overrides(&self) -> BTreeMap<String, f64> {
        self.overrides.clone()
    }

    /// Parameters as `(key, value, unit, source)` rows, in key order, after the overrides.
    fn parameters_table(&self) -> Vec<(String, f64, String, String)> {
        self.parameters()
            .iter()
            .map(|(k, p)| (k.to_string(), p.value, p.unit.clone(), p.source.clone()))
            .collect()
    }

    /// The value (SI) of a parameter by file key or study alias (`K_px`, ...).
    fn __getitem__(&self, name: &str) -> PyResult<f64> {
        let key = resolve_name(name);
        match self.parameters().parameter(key) {
            Some(p) => Ok(p.value),
            None if spec(key).is_some_and(|s| s.optional) => Err(to_py_err(LocoError::param(
                name,
                "optional and not given by this vehicle: the model computes it (its description \
                 in the parameter schema says how)",
            ))),
            None => Err(to_py_err(LocoError::param(
                name,
                "unknown vehicle parameter",
            ))),
        }
    }

    /// Total mass of the 25 bodies, kg.
    fn total_mass(&self) -> f64 {
        self.structure.total_mass()
    }

    /// The bogie mass m⁺ of the EN 14363 stability limit, kg: `assessment.bogie_mass` when the
    /// file or an override states it, else the heavier bogie's bodies.
    fn en14363_bogie_mass(&self) -> PyResult<f64> {
        loco_core::vehicle::model::bogie_mass::en14363_bogie_mass(&self.structure)
            .map_err(to_py_err)
    }

    /// Mean axle load, N: the weight over the wheelsets.
    fn mean_axle_load(&self) -> f64 {
        self.structure.mean_axle_load()
    }

    /// The 90 × 90 mass matrix `Σ Tᵀ diag(m, m, m, Ixx, Iyy, Izz) T` (kg, kg·m, kg·m²), in
    /// coordinate order.
    fn mass_matrix<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<f64>> {
        let mass = &self.structure.mass;
        Array2::from_shape_fn((N_DOF, N_DOF), |(i, j)| mass.get(i, j)).into_pyarray(py)
    }

    /// Pickled as the file text, origin and overrides; unpickling parses and builds again.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        let this = slf.get();
        let args = (
            this.toml_text.as_deref(),
            this.origin.as_str(),
            this.overrides.clone(),
        )
            .into_pyobject(py)?;
        Ok((slf.get_type().into_any(), args))
    }

    fn __repr__(&self) -> String {
        let source = match self.toml_text {
            None => "default vehicle".to_string(),
            Some(_) => format!("'{}'", self.origin),
        };
        if self.overrides.is_empty() {
            format!("Vehicle({source})")
        } else {
            let items: Vec<String> = self
                .overrides
                .iter()
                .map(|(k, v)| format!("'{k}': {v:?}"))
                .collect();
            format!("Vehicle({source}, overrides={{{}}})", items.join(", "))
        }
    }
}

/// Adds the class to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyVehicle>()
}
