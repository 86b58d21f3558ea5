//! The `loco.LocoError` exception hierarchy and the one helper that runs core code without the GIL.
//!
//! Every `loco_core::LocoError` variant maps to exactly one Python class here; the classes also
//! derive from the matching built-in (`ValueError`, `OSError`, `RuntimeError`) so that generic
//! handlers keep working.

use loco_core::error::FileKind;
use loco_core::LocoError as CoreError;
use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyKeyboardInterrupt};
use pyo3::prelude::*;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::sync::Mutex;
use std::time::Duration;

create_exception!(
    loco._loco,
    LocoError,
    PyException,
    "Base class of every error raised by loco."
);
create_exception!(
    loco._loco,
    ParameterError,
    LocoError,
    "A parameter or input array is not physical or has the wrong shape; the message names it."
);
create_exception!(
    loco._loco,
    ParameterRangeError,
    ParameterError,
    "A vehicle parameter is outside its physical range (the message names it, its value and the \
     range; list it in the vehicle file's `allow_out_of_range` to study it anyway)."
);
create_exception!(
    loco._loco,
    FileFormatError,
    LocoError,
    "An input file is malformed or not UTF-8 text; the message names the file and line \
     (subclasses say which kind of file; a batch study or samples file raises this class)."
);
create_exception!(
    loco._loco,
    ProfileFormatError,
    FileFormatError,
    "A wheel or rail profile file is malformed; the message names the file and line."
);
create_exception!(
    loco._loco,
    VehicleFormatError,
    FileFormatError,
    "A vehicle parameter file is not valid TOML or not UTF-8; the message names the file and line."
);
create_exception!(
    loco._loco,
    TrackFormatError,
    FileFormatError,
    "A measured-track or curve-sections file is malformed; the message names the file and line."
);
create_exception!(
    loco._loco,
    LocoIOError,
    LocoError,
    "A file could not be read or written."
);
create_exception!(
    loco._loco,
    ContactError,
    LocoError,
    "The wheel-rail contact search failed."
);
create_exception!(
    loco._loco,
    SimulationError,
    LocoError,
    "A time integration failed; subclasses say how."
);
create_exception!(
    loco._loco,
    DivergenceError,
    SimulationError,
    "The integration produced non-finite states or runaway amplitudes."
);
create_exception!(
    loco._loco,
    DerailmentError,
    SimulationError,
    "A wheel climbed past its flange."
);
create_exception!(
    loco._loco,
    EquilibriumError,
    SimulationError,
    "The static equilibrium a run or linearisation starts from was not found (Newton search)."
);
create_exception!(
    loco._loco,
    InternalError,
    LocoError,
    "A bug in loco (a Rust panic caught at the boundary); please report it."
);

/// Converts a core error into the Python exception of its class.
pub fn to_py_err(err: CoreError) -> PyErr {
    let msg = err.to_string();
    match err {
        CoreError::InvalidParameter { .. }
        | CoreError::InvalidParameterInFile { .. }
        | CoreError::InvalidInput { .. } => ParameterError::new_err(msg),
        CoreError::OutOfRange { .. } => ParameterRangeError::new_err(msg),
        CoreError::Parse { kind, .. } => match kind {
            FileKind::Profile => ProfileFormatError::new_err(msg),
            FileKind::Vehicle => VehicleFormatError::new_err(msg),
            FileKind::Track => TrackFormatError::new_err(msg),
            FileKind::Study => FileFormatError::new_err(msg),
        },
        CoreError::Io { .. } => LocoIOError::new_err(msg),
        CoreError::Contact(_) => ContactError::new_err(msg),
        CoreError::Diverged { .. } => DivergenceError::new_err(msg),
        CoreError::Derailed { .. } => DerailmentError::new_err(msg),
        CoreError::Equilibrium { .. } => EquilibriumError::new_err(msg),
        CoreError::Interrupted => PyKeyboardInterrupt::new_err(msg),
    }
}

/// What a detached computation gave: its result, or the payload of a panic.
type Outcome<T> = std::thread::Result<Result<T, CoreError>>;

/// Maps a detached computation's outcome to Python: core errors to their exception class, a
/// panic to `InternalError`.
fn map_outcome<T>(outcome: Outcome<T>) -> PyResult<T> {
    match outcome {
        Ok(result) => result.map_err(to_py_err),
        Err(panic) => {
            let what = loco_core::util::panic_message::panic_message(panic.as_ref());
            Err(InternalError::new_err(format!(
                "internal error (Rust panic): {what}"
            )))
        }
    }
}

/// Runs `work` with the GIL released, turns a core error into its Python exception and a panic
/// into `InternalError`, so that no Rust panic ever unwinds into Python.
///
/// Inputs must already be copied into owned Rust values (the closure cannot touch Python objects).
pub fn run_detached<T, F>(py: Python<'_>, work: F) -> PyResult<T>
where
    T: Send,
    F: FnOnce() -> Result<T, CoreError> + Send,
{
    map_outcome(py.detach(move || catch_unwind(AssertUnwindSafe(work))))
}

/// [`run_detached`] for long computations: `work` runs on a worker thread while this thread,
/// every 100 ms, takes the GIL to check for signals (Ctrl-C) and to call `poll` (progress). A
/// signal or an error from `poll` sets `cancel`, waits for `work` to stop and is raised.
pub fn run_detached_monitored<T, F, P>(
    py: Python<'_>,
    work: F,
    cancel: &AtomicBool,
    mut poll: P,
) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce() -> Result<T, CoreError> + Send + 'static,
    P: FnMut(Python<'_>) -> PyResult<()>,
{
    let (sender, receiver) = mpsc::channel::<Outcome<T>>();
    // A Mutex makes the receiver shareable with the detached closure; only this thread locks it.
    let receiver = Mutex::new(receiver);
    let worker = std::thread::spawn(move || {
        // The receiver only disappears if this function unwound; nothing is left to tell then.
        let _ = sender.send(catch_unwind(AssertUnwindSafe(work)));
    });
    let mut stopped_by: Option<PyErr> = None;
    let outcome = loop {
        let received = py.detach(|| match receiver.lock() {
            Ok(r) => r.recv_timeout(Duration::from_millis(100)),
            Err(_) => Err(RecvTimeoutError::Disconnected),
        });
        match received {
            Ok(outcome) => break outcome,
            Err(RecvTimeoutError::Disconnected) => {
                break Err(Box::new("worker thread ended without a result"))
            }
            Err(RecvTimeoutError::Timeout) => {}
        }
        if stopped_by.is_none() {
            if let Err(e) = py.check_signals().and_then(|()| poll(py)) {
                cancel.store(true, Ordering::Relaxed);
                stopped_by = Some(e);
            }
        }
    };
    // The worker has sent its outcome; joining only reaps the thread.
    let _ = py.detach(|| worker.join());
    if let Some(e) = stopped_by {
        return Err(e);
    }
    poll(py)?;
    map_outcome(outcome)
}

/// Adds the exception classes to the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("LocoError", py.get_type::<LocoError>())?;
    m.add("ParameterError", py.get_type::<ParameterError>())?;
    m.add("ParameterRangeError", py.get_type::<ParameterRangeError>())?;
    m.add("FileFormatError", py.get_type::<FileFormatError>())?;
    m.add("ProfileFormatError", py.get_type::<ProfileFormatError>())?;
    m.add("VehicleFormatError", py.get_type::<VehicleFormatError>())?;
    m.add("TrackFormatError", py.get_type::<TrackFormatError>())?;
    m.add("LocoIOError", py.get_type::<LocoIOError>())?;
    m.add("ContactError", py.get_type::<ContactError>())?;
    m.add("SimulationError", py.get_type::<SimulationError>())?;
    m.add("DivergenceError", py.get_type::<DivergenceError>())?;
    m.add("DerailmentError", py.get_type::<DerailmentError>())?;
    m.add("EquilibriumError", py.get_type::<EquilibriumError>())?;
    m.add("InternalError", py.get_type::<InternalError>())?;
    Ok(())
}
