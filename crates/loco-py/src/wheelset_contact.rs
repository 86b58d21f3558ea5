//! Bindings of `loco_core::contact`'s rigid contact geometry of a wheelset on a track: the
//! contact search prepared once for a wheelset's profiles, its points, rolling radius
//! difference and linear parameters, and the study's track and wheelset set-up.

use crate::contact::{to_vec, PyProfile};
use crate::errors::run_detached;
use loco_core::contact::linear_parameters::{linear_parameters, DEFAULT_AMPLITUDE};
use loco_core::contact::{
    rolling_radius_difference, ContactGeometry, ContactPoint, ContactSearchParams,
    ContactWorkspace, TrackSetup, WheelsetSetup,
};
use numpy::{AllowTypeChange, IntoPyArray, PyArray1, PyArrayLike1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// A wheelset's profiles on its rails with the track and wheelset set-up (gauge m, gauge_height
/// m below the rail top, rail_inclination rad, back_to_back m, flange_back_offset m, nominal radii
/// m), its contact search prepared once; every profile is given as a left-side profile.
#[pyclass(name = "WheelsetContact", module = "loco._loco", frozen)]
pub struct PyWheelsetContact {
    geometry: ContactGeometry,
}

#[pymethods]
impl PyWheelsetContact {
    #[new]
    #[pyo3(signature = (left_wheel, right_wheel, left_rail, right_rail, *, gauge, gauge_height,
        rail_inclination, back_to_back, flange_back_offset, nominal_radius_left,
        nominal_radius_right))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        left_wheel: PyRef<'_, PyProfile>,
        right_wheel: PyRef<'_, PyProfile>,
        left_rail: PyRef<'_, PyProfile>,
        right_rail: PyRef<'_, PyProfile>,
        gauge: f64,
        gauge_height: f64,
        rail_inclination: f64,
        back_to_back: f64,
        flange_back_offset: f64,
        nominal_radius_left: f64,
        nominal_radius_right: f64,
    ) -> PyResult<Self> {
        let wheels = [left_wheel.inner.clone(), right_wheel.inner.clone()];
        let rails = [left_rail.inner.clone(), right_rail.inner.clone()];
        let track = TrackSetup {
            gauge,
            gauge_height,
            rail_inclination,
        };
        let wheelset = WheelsetSetup {
            back_to_back,
            flange_back_offset,
            nominal_radius: [nominal_radius_left, nominal_radius_right],
        };
        let geometry = run_detached(py, move || {
            ContactGeometry::new(
                [&wheels[0], &wheels[1]],
                [&rails[0], &rails[1]],
                &track,
                &wheelset,
                &ContactSearchParams::default(),
            )
        })?;
        Ok(Self { geometry })
    }

    /// Rigid contact geometry at each lateral displacement `ys` (m). Returns a dict of arrays:
    /// `roll`, `rise` of shape (n,), and each point quantity of shape (n, 2, 2) indexed
    /// [y, wheel (0 left, 1 right), slot (0 tread side, 1 flange side)], NaN where absent.
    fn solve<'py>(
        &self,
        py: Python<'py>,
        ys: PyArrayLike1<'py, f64, AllowTypeChange>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let ys = to_vec(&ys)?;
        let g = &self.geometry;
        let n = ys.len();
        let (roll, rise, fields) = run_detached(py, move || {
            let mut ws = ContactWorkspace::default();
            let mut roll = vec![0.0; n];
            let mut rise = vec![0.0; n];
            let mut fields = vec![vec![f64::NAN; n * 4]; POINT_FIELDS.len()];
            let mut guess = g.roll_at_centre();
            for (i, &y) in ys.iter().enumerate() {
                let c = g.solve_with(y, guess, &mut ws)?;
                guess = c.roll;
                roll[i] = c.roll;
                rise[i] = c.rise;
                for (w, wheel) in c.wheels.iter().enumerate() {
                    for (k, point) in wheel.points.iter().enumerate() {
                        if let Some(p) = point {
                            for (f, v) in point_values(p).into_iter().enumerate() {
                                fields[f][i * 4 + w * 2 + k] = v;
                            }
                        }
                    }
                }
            }
            Ok((roll, rise, fields))
        })?;
        let out = PyDict::new(py);
        out.set_item("roll", roll.into_pyarray(py))?;
        out.set_item("rise", rise.into_pyarray(py))?;
        for (name, values) in POINT_FIELDS.iter().zip(fields) {
            out.set_item(*name, values.into_pyarray(py).reshape([n, 2, 2])?)?;
        }
        Ok(out)
    }

    /// Rolling radius difference r_left − r_right (m) at each `ys` (m), EN 15302's definition: the
    /// wheelset translated without roll (`loco_core::contact::rolling_radius_difference`).
    fn rolling_radius_difference<'py>(
        &self,
        py: Python<'py>,
        ys: PyArrayLike1<'py, f64, AllowTypeChange>,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let ys = to_vec(&ys)?;
        let g = &self.geometry;
        let dr = run_detached(py, move || rolling_radius_difference(g, &ys))?;
        Ok(dr.into_pyarray(py))
    }

    /// The linear contact parameters (`loco_core::contact::linear_parameters`) by central
    /// differences at ±`amplitude` (m): a dict of `amplitude`, `half_contact_spacing` (m),
    /// `rolling_radius` (m), `contact_angle` (rad), `conicity`, `contact_angle_parameter`,
    /// `roll_parameter` (–), `gravitational_stiffness_per_load` (1/m), and `axle_load` (N) with
    /// the `gravitational_stiffness` (N/m) under it (both NaN when no load is given).
    #[pyo3(signature = (amplitude=DEFAULT_AMPLITUDE, axle_load=None))]
    fn linear_parameters(
        &self,
        py: Python<'_>,
        amplitude: f64,
        axle_load: Option<f64>,
    ) -> PyResult<Vec<(&'static str, f64)>> {
        let g = &self.geometry;
        let (p, stiffness) = run_detached(py, move || {
            let p = linear_parameters(g, amplitude)?;
            let stiffness = match axle_load {
                Some(load) => p.gravitational_stiffness(load)?,
                None => f64::NAN,
            };
            Ok((p, stiffness))
        })?;
        Ok(vec![
            ("amplitude", p.amplitude),
            ("half_contact_spacing", p.half_contact_spacing),
            ("rolling_radius", p.rolling_radius),
            ("contact_angle", p.contact_angle),
            ("conicity", p.conicity),
            ("contact_angle_parameter", p.contact_angle_parameter),
            ("roll_parameter", p.roll_parameter),
            (
                "gravitational_stiffness_per_load",
                p.gravitational_stiffness_per_load,
            ),
            ("axle_load", axle_load.unwrap_or(f64::NAN)),
            ("gravitational_stiffness", stiffness),
        ])
    }
}

/// Names of the per-point quantities, in the order of [`point_values`].
const POINT_FIELDS: [&str; 9] = [
    "gap",
    "lateral",
    "vertical",
    "rolling_radius",
    "contact_angle",
    "wheel_curvature",
    "rail_curvature",
    "wheel_y",
    "rail_y",
];

fn point_values(p: &ContactPoint) -> [f64; 9] {
    [
        p.gap,
        p.lateral,
        p.vertical,
        p.rolling_radius,
        p.contact_angle,
        p.wheel_curvature,
        p.rail_curvature,
        p.wheel_y,
        p.rail_y,
    ]
}

/// The study's track and wheelset set-up, the defaults of the contact functions
/// (`TrackSetup::default()`, `WheelsetSetup::default()`): gauge (m), gauge_height (m below the
/// rail top), rail_inclination (rad), back_to_back (m), flange_back_offset (m),
/// nominal_radius_left and nominal_radius_right (m).
#[pyfunction]
fn contact_setup_defaults() -> Vec<(&'static str, f64)> {
    let track = TrackSetup::default();
    let wheelset = WheelsetSetup::default();
    vec![
        ("gauge", track.gauge),
        ("gauge_height", track.gauge_height),
        ("rail_inclination", track.rail_inclination),
        ("back_to_back", wheelset.back_to_back),
        ("flange_back_offset", wheelset.flange_back_offset),
        ("nominal_radius_left", wheelset.nominal_radius[0]),
        ("nominal_radius_right", wheelset.nominal_radius[1]),
    ]
}

/// Adds this file's functions and classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(contact_setup_defaults, m)?)?;
    m.add_class::<PyWheelsetContact>()?;
    // The default half step (m) of the linear contact parameters' central differences.
    m.add("LINEAR_PARAMETERS_AMPLITUDE", DEFAULT_AMPLITUDE)?;
    Ok(())
}
