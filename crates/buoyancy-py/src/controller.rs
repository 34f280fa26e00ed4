//! `Controller`: the core's engine-independent controller of floating bodies
//! (`buoyancy_core::controller`), for any engine that can hand over its bodies' states as NumPy
//! arrays: one call per step for every body, with the interpreter lock released.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, MutexGuard, TryLockError};

use buoyancy_core::controller::{
    BodyOptions, BodyState, Command, Controller, DampingResolution, Part, Settings, SharedSurface,
};
use buoyancy_core::nalgebra::{Point3, Translation3, UnitQuaternion, Vector3};
use buoyancy_core::water::WaterSurface;
use buoyancy_core::{DampingCoefficients, Error, Method, Pose, Water};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2};
use pyo3::exceptions::{PyIndexError, PyRuntimeError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};

use crate::airy::{PyAiryWave, PyWaves};
use crate::arrays;
use crate::convert::{self, given};
use crate::damping::PyDampingCoefficients;
use crate::errors::{arg_error, to_py, type_error};
use crate::float_report::PyFloatReport;
use crate::gerstner::PyGerstnerWaves;
use crate::height_grid::PyHeightGrid;
use crate::mesh::PyMesh;
use crate::stability::{self, PyEquilibrium};
use crate::step_inputs::{Columns, Input};
use crate::surface_function::{FunctionFailure, SurfaceFunction};
use crate::water::PyWater;
use crate::water_waves::Failure;
use buoyancy_core::query::Pressure;

/// One part of a body as given: the Python mesh (kept for `parts`), and its shape → body pose.
struct GivenPart {
    mesh: Py<PyMesh>,
    position: Vector3<f64>,
    rotation: UnitQuaternion<f64>,
}

/// A body's `water`: a still `Water`, or `None` when absent or `None`. Waves are a `ValueError`:
/// the waves are the controller's, shared by every body.
fn still_water(obj: Option<&Bound<'_, PyAny>>, name: &str) -> PyResult<Option<Water<f64>>> {
    let Some(water) = convert::instance::<PyWater>(obj, name)? else {
        return Ok(None);
    };
    let water = water.get();
    if water.waves.is_some() {
        return Err(arg_error(
            name,
            "a body's water must be still (its own density, level or normal): the waves are the controller's, shared by every body; give the Water with waves to the Controller (or set Controller.water) and a Water without waves here",
        ));
    }
    Ok(Some(water.inner))
}

/// A `HeightGrid` as the controller's surface: read at every evaluation, so that heights set in
/// place between steps are the ones the next step floats the bodies on.
struct GridSurface(Py<PyHeightGrid>);

impl WaterSurface<f64> for GridSurface {
    fn elevations(
        &self,
        water: &Water<f64>,
        points: &[Point3<f64>],
        time: f64,
        elevations: &mut [f64],
    ) -> Result<(), Error> {
        self.0
            .get()
            .with_surface(water, |s| s.elevations(water, points, time, elevations))
    }
    // No elevation bound: the heights may change (from another thread) between two
    // evaluations of one step, so every vertex is evaluated.
}

/// A Python callable `f(points, t)` as the controller's surface. The step runs without the
/// interpreter lock; each evaluation (one per part of a body) takes it for the call only. The
/// first failure of a step is kept, for `step` to raise.
struct FunctionSurface {
    function: Py<PyAny>,
    failure: Mutex<Option<FunctionFailure>>,
}

impl FunctionSurface {
    /// The first failure since the last call, if any.
    fn take_failure(&self) -> Option<FunctionFailure> {
        self.failure
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .take()
    }
}

impl WaterSurface<f64> for FunctionSurface {
    fn elevations(
        &self,
        water: &Water<f64>,
        points: &[Point3<f64>],
        time: f64,
        elevations: &mut [f64],
    ) -> Result<(), Error> {
        let surface = SurfaceFunction::new(&self.function);
        let result = surface.elevations(water, points, time, elevations);
        if let Some(failure) = surface.failure() {
            let mut first = self.failure.lock().unwrap_or_else(|p| p.into_inner());
            first.get_or_insert(failure);
        }
        result
    }
}

/// The controller's water with waves: the `Water` given, the core's surface of its waves and
/// their pressure, and that surface again when it is a Python callable (whose failures `step`
/// raises).
struct ControllerWaves {
    water: Py<PyWater>,
    surface: SharedSurface,
    pressure: Pressure,
    function: Option<Arc<FunctionSurface>>,
}

/// The controller's `water`: its still plane, and its waves as the core's surface (`None` for
/// still water) with their pressure.
fn controller_water(water: &Bound<'_, PyWater>) -> PyResult<(Water<f64>, Option<ControllerWaves>)> {
    let py = water.py();
    let inner = water.get().inner;
    let Some(waves) = &water.get().waves else {
        return Ok((inner, None));
    };
    let given = waves.given(py);
    let mut function = None;
    let mut pressure = Pressure::Hydrostatic;
    let surface: SharedSurface = if let Ok(wave) = given.cast::<PyAiryWave>() {
        Arc::new(PyWaves::single(wave.get())?.inner)
    } else if let Ok(waves) = given.cast::<PyWaves>() {
        let waves = waves.get();
        pressure = waves.pressure;
        Arc::new(waves.inner.clone())
    } else if let Ok(waves) = given.cast::<PyGerstnerWaves>() {
        Arc::new(waves.get().inner.clone())
    } else if let Ok(grid) = given.cast::<PyHeightGrid>() {
        Arc::new(GridSurface(grid.clone().unbind()))
    } else {
        // `Water` took it: a callable.
        let surface = Arc::new(FunctionSurface {
            function: given.unbind(),
            failure: Mutex::new(None),
        });
        function = Some(surface.clone());
        surface
    };
    Ok((
        inner,
        Some(ControllerWaves {
            water: water.clone().unbind(),
            surface,
            pressure,
            function,
        }),
    ))
}

/// The `water` argument of the controller: a `Water` (`default` when absent or `None`).
fn water_argument<'py>(
    py: Python<'py>,
    obj: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyWater>> {
    match convert::instance::<PyWater>(obj, "water")? {
        Some(water) => Ok(water.clone()),
        None => Bound::new(py, PyWater::still(Water::default())),
    }
}

/// `method`, or `None` when absent or `None`.
fn method(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Option<Method>> {
    given(obj).map(|m| convert::method(Some(m))).transpose()
}

/// `damping`, or `None` when absent or `None`.
fn damping(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Option<DampingCoefficients<f64>>> {
    Ok(convert::instance::<PyDampingCoefficients>(obj, "damping")?.map(|d| d.get().inner))
}

const RESOLUTION_EXPECTED: &str =
    "'full' or the most triangles of a reduced copy (a positive integer)";

/// `damping_resolution`: `"full"`, or the most triangles (a positive integer) of the reduced
/// copy of each mesh its pressure drag is integrated over; `None` when absent or `None`.
fn damping_resolution(obj: Option<&Bound<'_, PyAny>>) -> PyResult<Option<DampingResolution>> {
    const NAME: &str = "damping_resolution";
    let Some(obj) = given(obj) else {
        return Ok(None);
    };
    if let Ok(text) = obj.extract::<String>() {
        return match text.as_str() {
            "full" => Ok(Some(DampingResolution::Full)),
            _ => Err(arg_error(
                NAME,
                format!("expected {RESOLUTION_EXPECTED}, got {text:?}"),
            )),
        };
    }
    if obj.is_instance_of::<pyo3::types::PyBool>() {
        return Err(type_error(NAME, RESOLUTION_EXPECTED, obj));
    }
    match obj.extract::<i64>() {
        Ok(n) if n >= 1 => Ok(Some(DampingResolution::Reduced {
            max_triangles: usize::try_from(n).unwrap_or(usize::MAX),
        })),
        Ok(n) => Err(arg_error(
            NAME,
            format!("expected {RESOLUTION_EXPECTED}, got {n}"),
        )),
        Err(_) => Err(type_error(NAME, RESOLUTION_EXPECTED, obj)),
    }
}

/// A damping resolution as Python gives it: `"full"` or the most triangles of a reduced copy.
fn resolution_object(py: Python<'_>, resolution: DampingResolution) -> PyResult<Py<PyAny>> {
    Ok(match resolution {
        DampingResolution::Full => "full".into_pyobject(py)?.into_any().unbind(),
        DampingResolution::Reduced { max_triangles } => {
            max_triangles.into_pyobject(py)?.into_any().unbind()
        }
    })
}

/// The overrides of one body.
fn body_options(
    method_: Option<&Bound<'_, PyAny>>,
    water: Option<&Bound<'_, PyAny>>,
    damping_: Option<&Bound<'_, PyAny>>,
    resolution: Option<&Bound<'_, PyAny>>,
) -> PyResult<BodyOptions> {
    Ok(BodyOptions {
        method: method(method_)?,
        water: still_water(water, "water")?,
        damping: damping(damping_)?,
        damping_resolution: damping_resolution(resolution)?,
    })
}

const PARTS_EXPECTED: &str =
    "a Mesh, or a list of parts, each a Mesh or a (mesh, position, quaternion) tuple";

/// One item of `parts`: a `Mesh` (placed at the body's origin) or `(mesh, position,
/// quaternion)`.
fn part(item: &Bound<'_, PyAny>, name: &str) -> PyResult<GivenPart> {
    if let Ok(mesh) = item.cast::<PyMesh>() {
        return Ok(GivenPart {
            mesh: mesh.clone().unbind(),
            position: Vector3::zeros(),
            rotation: UnitQuaternion::identity(),
        });
    }
    let expected = "a Mesh or a (mesh, position, quaternion) tuple";
    let Ok(tuple) = item.cast::<PyTuple>() else {
        return Err(type_error(name, expected, item));
    };
    if tuple.len() != 3 {
        return Err(PyTypeError::new_err(format!(
            "{name}: expected {expected}, got a tuple of {} items",
            tuple.len()
        )));
    }
    let mesh = tuple.get_item(0)?;
    let mesh = mesh
        .cast::<PyMesh>()
        .map_err(|_| type_error(&format!("{name}[0]"), "a buoyancy.Mesh", &mesh))?;
    Ok(GivenPart {
        mesh: mesh.clone().unbind(),
        position: convert::vector3(&tuple.get_item(1)?, &format!("{name}[1] (position)"))?,
        rotation: convert::rotation(&tuple.get_item(2)?, &format!("{name}[2] (quaternion)"))?,
    })
}

/// Whether `parts` is one `(mesh, position, quaternion)` tuple rather than a tuple of parts: a
/// mesh, then something that is neither a mesh nor a tuple starting with one.
fn is_one_placed_part(parts: &Bound<'_, PyAny>) -> bool {
    let Ok(tuple) = parts.cast::<PyTuple>() else {
        return false;
    };
    let item = |k: usize| tuple.get_item(k).ok();
    let is_mesh = |obj: &Bound<'_, PyAny>| obj.cast::<PyMesh>().is_ok();
    let starts_with_mesh = |obj: &Bound<'_, PyAny>| {
        obj.cast::<PyTuple>()
            .is_ok_and(|t| t.get_item(0).is_ok_and(|m| is_mesh(&m)))
    };
    tuple.len() == 3
        && item(0).is_some_and(|m| is_mesh(&m))
        && item(1).is_some_and(|p| !is_mesh(&p) && !starts_with_mesh(&p))
}

/// The `parts` argument: one `Mesh`, one `(mesh, position, quaternion)` tuple, or a list (or
/// tuple) of parts.
fn given_parts(parts: &Bound<'_, PyAny>) -> PyResult<Vec<GivenPart>> {
    if parts.cast::<PyMesh>().is_ok() || is_one_placed_part(parts) {
        return Ok(vec![part(parts, "parts")?]);
    }
    let items: Vec<Bound<'_, PyAny>> = if let Ok(list) = parts.cast::<PyList>() {
        list.iter().collect()
    } else if let Ok(tuple) = parts.cast::<PyTuple>() {
        tuple.iter().collect()
    } else {
        return Err(type_error("parts", PARTS_EXPECTED, parts));
    };
    if items.is_empty() {
        return Err(arg_error(
            "parts",
            "a floating body needs at least one mesh",
        ));
    }
    items
        .iter()
        .enumerate()
        .map(|(k, item)| part(item, &format!("parts[{k}]")))
        .collect()
}

/// The core's parts of the given parts, whose meshes are shared, not copied: a mesh equal to
/// one that a body of the controller (`bodies`) or an earlier part is made of already (the same
/// object, or the same vertices and faces) is replaced in `parts` by that object and takes its
/// core mesh. Its reduced copy is then found, not built again, and the equal object given is
/// not kept alive by the controller.
fn core_parts(py: Python<'_>, parts: &mut [GivenPart], bodies: &[Vec<GivenPart>]) -> Vec<Part> {
    for k in 0..parts.len() {
        let (earlier, rest) = parts.split_at_mut(k);
        let part = &mut rest[0];
        let mesh = part.mesh.bind(py).get();
        let hash = mesh.content_hash();
        let held = bodies
            .iter()
            .flatten()
            .chain(earlier.iter())
            .find(|q| {
                let q = q.mesh.bind(py).get();
                std::ptr::eq(q, mesh) || (q.content_hash() == hash && q == mesh)
            })
            .map(|q| q.mesh.clone_ref(py));
        if let Some(held) = held {
            part.mesh = held;
        }
    }
    parts
        .iter()
        .map(|p| Part {
            mesh: p.mesh.bind(py).get().shared(),
            shape_to_body: Pose::from_parts(Translation3::from(p.position), p.rotation),
        })
        .collect()
}

/// Bodies that float, for any physics engine: the core's controller (``buoyancy-core``'s
/// ``controller`` module, also behind the Rust rapier adapter and :mod:`buoyancy.rapier`).
///
/// Each body is made of one or more closed meshes (its *parts*) placed on it. Once per step the
/// engine's glue reads every body's state into NumPy arrays, one row per body, and calls
/// :meth:`step`, which computes the exact buoyancy and the hydrodynamic damping of every body
/// (in parallel, without the interpreter lock) and returns, per body, a force and a torque to
/// **add** to what the engine holds for it, and whether to wake it.
///
/// Parameters
/// ----------
/// water : Water, optional
///     The water, still or with waves; default ``Water()`` (fresh, surface ``y = 0``, y up,
///     ``g = 9.81``, still). Gravity on the bodies is taken as the water's: ``g`` against its
///     normal, times each body's gravity scale. See *Waves* below.
/// method : str
///     The buoyancy method (see :data:`buoyancy.METHODS`), default ``"exact"``.
/// damping : DampingCoefficients, optional
///     The hydrodynamic damping, default ``DampingCoefficients()``;
///     ``DampingCoefficients.off()`` for none.
/// damping_resolution : int or str
///     How finely the pressure drag is integrated: over a reduced copy of at most this many
///     triangles (at least 64) of each mesh of more, built once per mesh when a body is added
///     (vertex clustering; a mesh no reduction keeps within 10 % of its area and volume is taken
///     whole), or ``"full"``: over every triangle, the model exactly. Default 384 (the bunny of
///     5,002 triangles becomes 362; its drag within 5 % of the full drag's force). The buoyancy
///     always takes the full mesh.
///
/// The controller's settings apply to every body added without an override.
///
/// Forces the application adds itself
///     Engines such as rapier keep the forces added to a body until they are reset. The
///     controller never asks to reset them: it remembers the force and torque it had added (its
///     *share*, in ``float32`` like the engine's) and asks to add only the difference, so the
///     engine holds *the application's own forces + this step's buoyancy and damping*. After
///     resetting a body's forces, call :meth:`forget_applied`; :meth:`remove` returns what to
///     add to take the share back off. A dynamic body whose applied force and torque are both
///     exactly zero while the share is not had them reset by the engine: the share is
///     forgotten, and the whole share is added again.
///
/// Bodies the engine does not move by forces
///     (``dynamic`` False: kinematic, fixed, disabled) get nothing computed and keep their
///     share, so that a body made kinematic and dynamic again gets its buoyancy once.
///
/// Sleeping bodies
///     are woken (``wake``) when the controller's force or torque on them has changed by more
///     than 0.1 % (of the force plus the body's weight) since they were last awake, and when
///     they fell asleep out of balance (net force above 0.1 % of the weight, or net torque
///     above that times the body's size), unless woken for that at the same pose before.
///
/// Stability
///     The damping is semi-implicit: the damping wrench ``W`` of the model is applied as
///     ``(W − α·dt·G) / (1 + α·dt)``, with ``G`` the step's buoyancy, gravity and the
///     application's own forces and ``α = √(W·M⁻¹W / q̇·M·q̇)`` the damping rate in the metric of
///     the body's mass and inertia, so that light bodies reach the model's terminal velocity and
///     bodies dropped fast do not overshoot. Where that one rate would throw a direction of
///     motion back faster than it came (a fast spin under a strong angular damping while the
///     body sinks fast), the damping is taken implicitly through its stiffness ``K = −∂W/∂q̇``
///     instead, each direction at its own rate. A body whose pose, velocity or result is not
///     finite gets no force (its share is taken back); its report's outcome is ``"not_finite"``.
///
/// Waves
///     The water may carry waves (``Water(waves=...)``: an :class:`AiryWave`, :class:`Waves`
///     such as ``Waves.jonswap(...)``, :class:`GerstnerWaves`, a :class:`HeightGrid` or a
///     callable ``f(points, t)``). The bodies then float on the surface at the controller's
///     :attr:`time` (s), which every :meth:`step` advances by its ``dt``: the buoyancy is the
///     pressure of the waves integrated exactly over each part's wetted surface: the
///     hydrostatic ``ρ g (η − h)``, or under ``Waves`` of ``pressure="froude_krylov"`` the linear
///     Froude–Krylov pressure (``method`` holds there too: ``"exact"`` and ``"exact_surface"``
///     integrate exactly; under a method that assumes a flat surface a body gets no force and
///     its report's outcome is ``"unsupported"``), and the damping is taken relative to the water's
///     velocity at the body's center of mass: the orbital velocity of Airy waves (and
///     ``Waves``); Gerstner waves, height grids and callables move no water. The waves are the
///     controller's, shared by every body: a body's own ``water`` must be still.
///
///     A callable is called once per part of each body per step, from the threads of the step,
///     each call holding the interpreter lock (the rest of the step runs without it). If it
///     raises (or returns other than one finite elevation per point), :meth:`step` raises that
///     error and the controller is left as it was before the call: nothing applied, the time
///     not advanced. A :class:`HeightGrid` is read at every evaluation: heights set between two
///     steps float the bodies at the next one.
///
/// Bodies are numbered from 0 in the order they were added; :meth:`remove` moves the last body
/// into the freed number. World frame, SI units, torques about each body's center of mass;
/// quaternions ``(x, y, z, w)``.
///
/// :meth:`step` releases the interpreter lock, so other Python threads run meanwhile. A
/// controller may be shared by threads: it serves one call at a time, and a call from another
/// thread during a step waits for it (without the interpreter lock). A call from within its own
/// step (a surface function of its water calling back into it) raises ``RuntimeError``. A
/// controller does not pickle (it is one simulation's running state); its meshes and water do.
///
/// Examples
/// --------
/// A 1 m cube of 500 kg at rest with its center at the water level gets its weight, 4905 N:
///
/// >>> controller = buoyancy.Controller()                 # fresh water, surface y = 0
/// >>> cube = controller.add(buoyancy.shapes.cube())      # body 0: one part, on its origin
/// >>> add_force, add_torque, wake = controller.step(
/// ...     1 / 60,                                        # dt, s
/// ...     positions=np.zeros((1, 3)),                    # body frame → world, m
/// ...     quaternions=np.array([[0.0, 0.0, 0.0, 1.0]]),  # (x, y, z, w)
/// ...     centers_of_mass=np.zeros((1, 3)),              # world, m
/// ...     linear_velocities=np.zeros((1, 3)),            # m/s
/// ...     angular_velocities=np.zeros((1, 3)),           # rad/s
/// ...     masses=np.array([500.0]),                      # kg
/// ...     inverse_masses=np.full((1, 3), 1 / 500),       # 1/kg, per world axis
/// ...     inverse_inertias=np.eye(3)[None] * 6 / 500,    # world, 1/(kg·m²)
/// ...     gravity_scales=np.ones(1),
/// ...     applied_forces=np.zeros((1, 3), np.float32),   # what the engine holds, N
/// ...     applied_torques=np.zeros((1, 3), np.float32),  # N·m
/// ...     dynamic=np.array([True]),
/// ...     sleeping=np.array([False]),
/// ... )
/// >>> add_force.tolist(), wake.tolist()    # add this to the engine's force; it is awake
/// ([[0.0, 4905.0, 0.0]], [False])
/// >>> report = controller.report(cube)
/// >>> report.outcome, report.submerged_volume
/// ('applied', 0.5)
///
/// On a swell 20 m long and 0.2 m high, the cube held at the same place feels the surface at
/// the controller's time, which the step advanced by ``dt``:
///
/// >>> swell = buoyancy.Water(waves=buoyancy.AiryWave(amplitude=0.1, wavelength=20.0))
/// >>> controller = buoyancy.Controller(swell)
/// >>> cube = controller.add(buoyancy.shapes.cube())
/// >>> arrays = dict(positions=np.zeros((1, 3)), quaternions=[[0.0, 0.0, 0.0, 1.0]],
/// ...               centers_of_mass=np.zeros((1, 3)), linear_velocities=np.zeros((1, 3)),
/// ...               angular_velocities=np.zeros((1, 3)), masses=[500.0], inverse_masses=[1 / 500],
/// ...               inverse_inertias=np.eye(3)[None] * 6 / 500, gravity_scales=[1.0],
/// ...               applied_forces=np.zeros((1, 3), np.float32),
/// ...               applied_torques=np.zeros((1, 3), np.float32), dynamic=[True], sleeping=[False])
/// >>> _ = controller.step(0.5, **arrays)               # at t = 0: the crest is on the cube
/// >>> controller.time                                  # s
/// 0.5
/// >>> round(controller.report(cube).submerged_volume, 3)  # m³, 0.5 in still water
/// 0.599
#[pyclass(frozen, module = "buoyancy", name = "Controller")]
pub struct PyController {
    state: Mutex<ControllerState>,
    /// The thread holding `state` (see [`thread_number`]), 0 when none does.
    owner: AtomicU64,
}

impl PyController {
    /// The controller's state, for this thread alone until the guard is dropped. Another
    /// thread's call waits for it, with the interpreter lock released (the holder may need the
    /// interpreter: a step on a surface function calls it). A call from within the holder's
    /// own work (the surface function calling back into its controller) is a `RuntimeError`,
    /// where waiting would never end.
    fn lock(&self, py: Python<'_>) -> PyResult<StateGuard<'_>> {
        let me = thread_number();
        loop {
            match self.state.try_lock() {
                Ok(state) => return Ok(StateGuard::new(state, &self.owner, me)),
                // A panic while held (reported as a `PanicException`) leaves the state as the
                // core left it: every core operation keeps it consistent.
                Err(TryLockError::Poisoned(poisoned)) => {
                    return Ok(StateGuard::new(poisoned.into_inner(), &self.owner, me));
                }
                Err(TryLockError::WouldBlock) => {}
            }
            if self.owner.load(Ordering::Acquire) == me {
                return Err(PyRuntimeError::new_err(
                    "the Controller was called from within its own step (by the water's surface \
                     function?): a step cannot be interrupted by another call on the same \
                     controller",
                ));
            }
            // Wait for the holder without the interpreter lock, then try again with it.
            py.detach(|| drop(self.state.lock()));
        }
    }
}

/// A number for the calling thread, from 1, unique in the process.
fn thread_number() -> u64 {
    static NEXT: AtomicU64 = AtomicU64::new(1);
    thread_local! {
        static NUMBER: u64 = NEXT.fetch_add(1, Ordering::Relaxed);
    }
    NUMBER.with(|n| *n)
}

/// A held lock on a controller's state, which records the thread holding it.
struct StateGuard<'a> {
    state: MutexGuard<'a, ControllerState>,
    owner: &'a AtomicU64,
}

impl<'a> StateGuard<'a> {
    fn new(state: MutexGuard<'a, ControllerState>, owner: &'a AtomicU64, me: u64) -> Self {
        owner.store(me, Ordering::Release);
        StateGuard { state, owner }
    }
}

impl Drop for StateGuard<'_> {
    fn drop(&mut self) {
        self.owner.store(0, Ordering::Release);
    }
}

impl std::ops::Deref for StateGuard<'_> {
    type Target = ControllerState;
    fn deref(&self) -> &ControllerState {
        &self.state
    }
}

impl std::ops::DerefMut for StateGuard<'_> {
    fn deref_mut(&mut self) -> &mut ControllerState {
        &mut self.state
    }
}

/// What a `Controller` holds, behind its lock.
struct ControllerState {
    inner: Controller,
    /// The parts of each body as given, in the controller's numbering.
    parts: Vec<Vec<GivenPart>>,
    /// Each step's states and commands, kept so that a step does not allocate them.
    states: Vec<BodyState>,
    commands: Vec<Command>,
    /// The water given, with its waves' surface, when it has waves.
    sea: Option<ControllerWaves>,
}

impl ControllerState {
    /// The controller's water, with its waves if it has any.
    fn water<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyWater>> {
        match &self.sea {
            Some(sea) => Ok(sea.water.bind(py).clone()),
            None => Bound::new(py, PyWater::still(self.inner.settings().water)),
        }
    }

    /// Makes the bodies float in `water` (its still plane, and its waves if it has any).
    fn set_sea(&mut self, water: &Bound<'_, PyWater>) -> PyResult<()> {
        let (inner, sea) = controller_water(water)?;
        self.inner.settings_mut().water = inner;
        self.inner
            .set_surface(sea.as_ref().map(|sea| sea.surface.clone()));
        self.inner.set_pressure(
            sea.as_ref()
                .map_or(Pressure::Hydrostatic, |sea| sea.pressure),
        );
        self.sea = sea;
        Ok(())
    }

    /// `index` as a body number, or an `IndexError`.
    fn body(&self, index: &Bound<'_, PyAny>) -> PyResult<usize> {
        let n = self.inner.len();
        let i = convert::index(index, "index")?;
        i.and_then(|i| usize::try_from(i).ok())
            .filter(|&i| i < n)
            .ok_or_else(|| {
                PyIndexError::new_err(format!(
                    "index: no body {}; the controller has {n} (numbered from 0)",
                    convert::python_str(index)
                ))
            })
    }
}

/// `step`'s result: the forces and torques to add, and whether to wake each body.
type StepResult<'py> = (
    Bound<'py, PyArray2<f32>>,
    Bound<'py, PyArray2<f32>>,
    Bound<'py, PyArray1<bool>>,
);

/// `remove`'s result: the force and torque to add to take the share back off.
type TakeBack<'py> = (Bound<'py, PyArray1<f32>>, Bound<'py, PyArray1<f32>>);

#[pymethods]
impl PyController {
    #[new]
    #[pyo3(
        signature = (water=None, method=None, damping=None, damping_resolution=None),
        text_signature = "(water=None, method='exact', damping=None, damping_resolution=384)"
    )]
    fn py_new(
        py: Python<'_>,
        water: Option<&Bound<'_, PyAny>>,
        method: Option<&Bound<'_, PyAny>>,
        damping: Option<&Bound<'_, PyAny>>,
        damping_resolution: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let water = water_argument(py, water)?;
        let settings = Settings {
            water: Water::default(),
            method: self::method(method)?.unwrap_or(Method::Exact),
            damping: self::damping(damping)?.unwrap_or_default(),
        };
        let mut inner = Controller::new(settings);
        if let Some(resolution) = self::damping_resolution(damping_resolution)? {
            inner.set_damping_resolution(resolution);
        }
        let mut state = ControllerState {
            inner,
            parts: Vec::new(),
            states: Vec::new(),
            commands: Vec::new(),
            sea: None,
        };
        state.set_sea(&water)?;
        Ok(PyController {
            state: Mutex::new(state),
            owner: AtomicU64::new(0),
        })
    }

    /// The controller's water, with its waves if it has any (a body's ``water`` overrides its
    /// still plane, density and gravity, not the waves). Setting it keeps :attr:`time`.
    #[getter]
    fn get_water<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyWater>> {
        self.lock(py)?.water(py)
    }
    #[setter]
    fn set_water(&self, py: Python<'_>, water: &Bound<'_, PyAny>) -> PyResult<()> {
        let mut guard = self.lock(py)?;
        let this = &mut *guard;
        if water.is_none() {
            return Err(type_error("water", "a buoyancy.Water", water));
        }
        let water = water_argument(water.py(), Some(water))?;
        this.set_sea(&water)
    }

    /// The time of the water's waves, s: the bodies are floated on the surface at this time,
    /// and every :meth:`step` advances it by its ``dt``. Starts at 0; set it to any finite
    /// number (e.g. to restart a sea, or to match a world's clock). Kept when :attr:`water`
    /// changes; it also runs in still water.
    #[getter]
    fn get_time(&self, py: Python<'_>) -> PyResult<f64> {
        Ok(self.lock(py)?.inner.time())
    }
    #[setter]
    fn set_time(&self, py: Python<'_>, time: &Bound<'_, PyAny>) -> PyResult<()> {
        let mut guard = self.lock(py)?;
        let this = &mut *guard;
        if time.is_none() {
            return Err(type_error("time", "a number (s)", time));
        }
        this.inner.set_time(convert::time(Some(time), "time")?);
        Ok(())
    }

    /// The controller's buoyancy method, as its canonical name (``"exact"``, …).
    #[getter]
    fn get_method(&self, py: Python<'_>) -> PyResult<&'static str> {
        Ok(self.lock(py)?.inner.settings().method.name())
    }
    #[setter]
    fn set_method(&self, py: Python<'_>, method: &Bound<'_, PyAny>) -> PyResult<()> {
        let mut guard = self.lock(py)?;
        let this = &mut *guard;
        if method.is_none() {
            return Err(type_error(
                "method",
                "a method name such as 'exact'",
                method,
            ));
        }
        this.inner.settings_mut().method = convert::method(Some(method))?;
        Ok(())
    }

    /// The controller's damping coefficients.
    #[getter]
    fn get_damping(&self, py: Python<'_>) -> PyResult<PyDampingCoefficients> {
        Ok(PyDampingCoefficients {
            inner: self.lock(py)?.inner.settings().damping,
        })
    }
    #[setter]
    fn set_damping(&self, py: Python<'_>, damping: &Bound<'_, PyAny>) -> PyResult<()> {
        let mut guard = self.lock(py)?;
        let this = &mut *guard;
        if damping.is_none() {
            return Err(type_error(
                "damping",
                "a buoyancy.DampingCoefficients",
                damping,
            ));
        }
        this.inner.settings_mut().damping = self::damping(Some(damping))?.unwrap_or_default();
        Ok(())
    }

    /// How finely the pressure drag of the bodies without their own is integrated: the most
    /// triangles of the reduced copy of each mesh (an int), or ``"full"``. Setting it builds the
    /// reduced copies it asks for (once per mesh).
    #[getter]
    fn get_damping_resolution(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        let guard = self.lock(py)?;
        let this = &*guard;
        resolution_object(py, this.inner.damping_resolution())
    }
    #[setter]
    fn set_damping_resolution(
        &self,
        py: Python<'_>,
        resolution: &Bound<'_, PyAny>,
    ) -> PyResult<()> {
        let mut guard = self.lock(py)?;
        let this = &mut *guard;
        let Some(resolution) = self::damping_resolution(Some(resolution))? else {
            return Err(type_error(
                "damping_resolution",
                RESOLUTION_EXPECTED,
                resolution,
            ));
        };
        this.inner.set_damping_resolution(resolution);
        Ok(())
    }

    /// The damping resolution body ``index`` has: its own, else the controller's (see
    /// :attr:`damping_resolution`). ``IndexError`` if there is no such body.
    fn body_damping_resolution(
        &self,
        py: Python<'_>,
        index: &Bound<'_, PyAny>,
    ) -> PyResult<Py<PyAny>> {
        let guard = self.lock(py)?;
        let this = &*guard;
        let i = this.body(index)?;
        let resolution = this
            .inner
            .body_damping_resolution(i)
            .unwrap_or_else(|| unreachable!("body {i} was checked to exist"));
        resolution_object(py, resolution)
    }

    fn __len__(&self, py: Python<'_>) -> PyResult<usize> {
        Ok(self.lock(py)?.inner.len())
    }

    /// A controller does not pickle: it is the running books of a simulation (each body's
    /// share of the engine's forces, its damping state, the last evaluation), which mean
    /// nothing to another process's engine. Its meshes, water and waves pickle.
    fn __reduce__(&self) -> PyResult<()> {
        Err(PyTypeError::new_err(
            "a Controller cannot be pickled: it holds the running state of one simulation (each \
             body's share of the engine's forces, its damping state); send its meshes, water and \
             waves (which pickle) and build a Controller in the other process",
        ))
    }

    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let guard = self.lock(py)?;
        let this = &*guard;
        let water = this.water(py)?.repr()?;
        let time = match this.sea {
            Some(_) => format!(", time={}", crate::format::g(this.inner.time())),
            None => String::new(),
        };
        Ok(format!(
            "Controller({} bodies, water={water}, method='{}'{time})",
            this.inner.len(),
            this.inner.settings().method.name()
        ))
    }

    /// Adds a body; returns its number (the count of bodies before it).
    ///
    /// Parameters
    /// ----------
    /// parts : Mesh or list
    ///     The body's closed meshes: one :class:`Mesh`, in the body's frame, or a list of
    ///     parts, each a ``Mesh`` in the body's frame or a tuple ``(mesh, position,
    ///     quaternion)`` of a mesh in its own frame and the pose of that frame in the body's
    ///     (``x_body = R @ x_mesh + position``; a quaternion ``(x, y, z, w)`` or a 3×3 rotation
    ///     matrix). The body's frame is the one of the ``positions`` and ``quaternions`` given
    ///     to :meth:`step`. A ``Mesh`` is shared, not copied: the bodies made of the same
    ///     ``Mesh`` share it, and the reduced copy its damping is integrated over, built once.
    ///     A ``Mesh`` equal to one a body is made of already (same vertices and faces) is
    ///     replaced by that one, so that equal meshes built apart are not all kept.
    /// method : str, optional
    ///     This body's method; default the controller's.
    /// water : Water, optional
    ///     This body's still water (its density, level, normal and gravity); default the
    ///     controller's. It floats on the controller's waves, if any: a water with waves here
    ///     is a ``ValueError``.
    /// damping : DampingCoefficients, optional
    ///     This body's damping; default the controller's.
    /// damping_resolution : int or str, optional
    ///     How finely this body's pressure drag is integrated (see :class:`Controller`); default
    ///     the controller's.
    ///
    /// Buoyancy and pressure drag add up over the parts; the angular damping is the whole
    /// body's (total volume, total wetted fraction), so that splitting a shape into parts does
    /// not change it.
    ///
    /// >>> controller = buoyancy.Controller()
    /// >>> cube = buoyancy.shapes.cube()
    /// >>> controller.add([(cube, (-1, 0, 0), (0, 0, 0, 1)), (cube, (1, 0, 0), (0, 0, 0, 1))])
    /// 0
    /// >>> len(controller.parts(0))
    /// 2
    #[pyo3(
        signature = (parts, method=None, water=None, damping=None, damping_resolution=None),
        text_signature = "(self, parts, method=None, water=None, damping=None, damping_resolution=None)"
    )]
    fn add(
        &self,
        py: Python<'_>,
        parts: &Bound<'_, PyAny>,
        method: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyAny>>,
        damping: Option<&Bound<'_, PyAny>>,
        damping_resolution: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<usize> {
        let mut guard = self.lock(py)?;
        let this = &mut *guard;
        let mut given = given_parts(parts)?;
        let options = body_options(method, water, damping, damping_resolution)?;
        let index = this
            .inner
            .add(core_parts(py, &mut given, &this.parts), options)
            .map_err(|e| to_py(e, Some("parts")))?;
        this.parts.push(given);
        Ok(index)
    }

    /// Replaces the parts and overrides of body ``index`` (arguments as in :meth:`add`),
    /// keeping the books of what was applied to it. ``IndexError`` if there is no such body.
    #[pyo3(
        signature = (index, parts, method=None, water=None, damping=None, damping_resolution=None),
        text_signature = "(self, index, parts, method=None, water=None, damping=None, damping_resolution=None)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn replace(
        &self,
        py: Python<'_>,
        index: &Bound<'_, PyAny>,
        parts: &Bound<'_, PyAny>,
        method: Option<&Bound<'_, PyAny>>,
        water: Option<&Bound<'_, PyAny>>,
        damping: Option<&Bound<'_, PyAny>>,
        damping_resolution: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<()> {
        let mut guard = self.lock(py)?;
        let this = &mut *guard;
        let i = this.body(index)?;
        let mut given = given_parts(parts)?;
        let options = body_options(method, water, damping, damping_resolution)?;
        this.inner
            .replace(i, core_parts(py, &mut given, &this.parts), options)
            .map_err(|e| to_py(e, Some("parts")))?;
        this.parts[i] = given;
        Ok(())
    }

    /// Removes body ``index`` and returns ``(force, torque)``, float32 arrays of shape (3,),
    /// N and N·m: what to add to the engine's force and torque to take the controller's share
    /// back off the body. Add it even to a body the engine does not move by forces (the share
    /// is there: with rapier, make the body dynamic for the time of the addition). The last
    /// body takes the number ``index``. ``IndexError`` if there is no such body.
    fn remove<'py>(&self, py: Python<'py>, index: &Bound<'_, PyAny>) -> PyResult<TakeBack<'py>> {
        let mut guard = self.lock(py)?;
        let this = &mut *guard;
        let i = this.body(index)?;
        let command = this
            .inner
            .remove(i)
            .unwrap_or_else(|| unreachable!("body {i} was checked to exist"));
        this.parts.swap_remove(i);
        Ok((
            PyArray1::from_slice(py, command.add_force.as_slice()),
            PyArray1::from_slice(py, command.add_torque.as_slice()),
        ))
    }

    /// Tells the controller that the engine's forces and torques of body ``index`` were reset,
    /// so that its share is zero now; the next :meth:`step` adds the whole share again.
    /// ``IndexError`` if there is no such body.
    fn forget_applied(&self, py: Python<'_>, index: &Bound<'_, PyAny>) -> PyResult<()> {
        let mut guard = self.lock(py)?;
        let this = &mut *guard;
        let i = this.body(index)?;
        this.inner.forget_applied(i);
        Ok(())
    }

    /// What the last :meth:`step` computed and applied for body ``index``
    /// (a :class:`FloatReport`). ``IndexError`` if there is no such body.
    fn report(&self, py: Python<'_>, index: &Bound<'_, PyAny>) -> PyResult<PyFloatReport> {
        let guard = self.lock(py)?;
        let this = &*guard;
        let i = this.body(index)?;
        let inner = *this
            .inner
            .report(i)
            .unwrap_or_else(|| unreachable!("body {i} was checked to exist"));
        Ok(PyFloatReport { inner })
    }

    /// Where body ``index`` comes to rest in the still water (the still level under waves), for
    /// its mass and center of mass: the pose at which the water it displaces weighs what it
    /// weighs and its center of buoyancy lies on the vertical through its center of mass, the
    /// stable attitude (see :meth:`Mesh.equilibrium`; a body of several parts is solved as one
    /// mesh, its parts merged). Heel and trim are measured from the given orientation, whose yaw
    /// and the horizontal position of the center of mass are kept. An engine's glue sets the body
    /// there, at rest, before the first step.
    ///
    /// Parameters
    /// ----------
    /// index : int
    /// position : array_like, shape (3,)
    ///     The body's position now, world frame, m.
    /// quaternion : array_like, shape (4,)
    ///     Its orientation now, ``(x, y, z, w)``.
    /// center_of_mass : array_like, shape (3,)
    ///     Its center of mass now, world frame, m.
    /// mass : float
    ///     Kg, positive.
    /// gravity_scale : float
    ///     The factor of gravity on the body (default 1): it weighs ``mass * gravity_scale``.
    ///
    /// Returns
    /// -------
    /// (ndarray, ndarray, Equilibrium)
    ///     The body's position (3,) and quaternion (4,) at rest, and the equilibrium (draft,
    ///     heel, trim, GM, ...). ``IndexError`` for no such body, ``ValueError`` for a body
    ///     that does not float, ``RuntimeError`` if the solver does not converge.
    #[pyo3(
        signature = (index, position, quaternion, center_of_mass, mass, gravity_scale=None),
        text_signature = "(self, index, position, quaternion, center_of_mass, mass, gravity_scale=1.0)"
    )]
    #[allow(clippy::type_complexity, clippy::too_many_arguments)]
    fn rest<'py>(
        &self,
        py: Python<'py>,
        index: &Bound<'_, PyAny>,
        position: &Bound<'_, PyAny>,
        quaternion: &Bound<'_, PyAny>,
        center_of_mass: &Bound<'_, PyAny>,
        mass: &Bound<'_, PyAny>,
        gravity_scale: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<(
        Bound<'py, PyArray1<f64>>,
        Bound<'py, PyArray1<f64>>,
        PyEquilibrium,
    )> {
        let guard = self.lock(py)?;
        let this = &*guard;
        let i = this.body(index)?;
        let pose = Pose::from_parts(
            Translation3::from(convert::vector3(position, "position")?),
            convert::rotation(quaternion, "quaternion")?,
        );
        let mass = convert::real(mass, "mass")?;
        let state = BodyState {
            pose,
            center_of_mass: Point3::from(convert::vector3(center_of_mass, "center_of_mass")?),
            linear_velocity: Vector3::zeros(),
            angular_velocity: Vector3::zeros(),
            mass,
            inverse_mass: Vector3::zeros(),
            inverse_inertia: Default::default(),
            gravity_scale: convert::real_or(gravity_scale, "gravity_scale", 1.0)?,
            applied_force: Vector3::zeros(),
            applied_torque: Vector3::zeros(),
            motion: Default::default(),
            sleeping: false,
        };
        let controller = &this.inner;
        let rest = py
            .detach(|| controller.rest(i, &state))
            .unwrap_or_else(|| unreachable!("body {i} was checked to exist"))
            .map_err(stability::rest_error)?;
        let q = rest.pose.rotation.coords;
        Ok((
            arrays::vector(py, rest.pose.translation.vector.as_slice()),
            arrays::vector(py, &[q.x, q.y, q.z, q.w]),
            PyEquilibrium::from(rest.equilibrium),
        ))
    }

    /// The parts of body ``index``: a list of ``(mesh, position, quaternion)``, each mesh the
    /// object given to :meth:`add` (or the equal one the controller held already) and its pose
    /// in the body's frame (arrays of shape (3,) and (4,), the quaternion ``(x, y, z, w)``).
    /// ``IndexError`` if there is no such body.
    #[allow(clippy::type_complexity)]
    fn parts<'py>(
        &self,
        py: Python<'py>,
        index: &Bound<'_, PyAny>,
    ) -> PyResult<
        Vec<(
            Bound<'py, PyMesh>,
            Bound<'py, PyArray1<f64>>,
            Bound<'py, PyArray1<f64>>,
        )>,
    > {
        let guard = self.lock(py)?;
        let this = &*guard;
        let i = this.body(index)?;
        Ok(this.parts[i]
            .iter()
            .map(|p| {
                let q = p.rotation.coords;
                (
                    p.mesh.bind(py).clone(),
                    arrays::vector(py, p.position.as_slice()),
                    arrays::vector(py, &[q.x, q.y, q.z, q.w]),
                )
            })
            .collect())
    }

    /// One step of ``dt`` seconds for every body: its buoyancy and damping at the state given,
    /// and what to add to the engine's force and torque for it.
    ///
    /// Every array has one row per body, in the controller's numbering (``N = len(self)``).
    /// Arrays of the right dtype are read in place, others are converted first. The pose,
    /// center of mass and velocities may be NaN or infinite: the body then gets no force and
    /// its report says ``"not_finite"``.
    ///
    /// Parameters
    /// ----------
    /// dt : float
    ///     The step, s, finite and non-negative (the damping's semi-implicit scheme needs it).
    ///     The bodies are evaluated on the water's waves at :attr:`time`, which then advances
    ///     by ``dt``.
    /// positions : array_like, shape (N, 3)
    ///     Origin of each body's frame (the frame its parts are placed in), world, m.
    /// quaternions : array_like, shape (N, 4)
    ///     Rotation of each body's frame, ``(x, y, z, w)``; normalised (a finite one whose norm
    ///     is off 1 by more than :data:`QUATERNION_TOLERANCE` is a ``ValueError``).
    /// centers_of_mass : array_like, shape (N, 3)
    ///     World centers of mass, m: the torques are about them.
    /// linear_velocities : array_like, shape (N, 3)
    ///     Velocities of the centers of mass, m/s.
    /// angular_velocities : array_like, shape (N, 3)
    ///     Angular velocities, rad/s.
    /// masses : array_like, shape (N,)
    ///     Masses, kg, finite and non-negative.
    /// inverse_masses : array_like, shape (N, 3) or (N,)
    ///     Inverse masses, 1/kg, per world axis (zero on a locked translation axis) or one per
    ///     body; finite and non-negative.
    /// inverse_inertias : array_like, shape (N, 3, 3)
    ///     World inverse inertia tensors about the centers of mass, 1/(kg·m²) (zero rows and
    ///     columns on locked rotation axes), finite.
    /// gravity_scales : array_like, shape (N,)
    ///     The factor of gravity on each body, finite.
    /// applied_forces, applied_torques : array_like, shape (N, 3), float32
    ///     The force (N) and torque (N·m, about the center of mass) the engine holds for each
    ///     body: the application's own plus the controller's share (float64 is rounded to
    ///     float32, what the controller keeps its share in).
    /// dynamic : array_like of bool, shape (N,)
    ///     Whether the engine moves each body by forces (False: kinematic, fixed, disabled).
    /// sleeping : array_like of bool, shape (N,)
    ///     Whether each body sleeps.
    ///
    /// Returns
    /// -------
    /// add_forces : ndarray, shape (N, 3), float32
    ///     Force to add to what the engine holds for each body, N (zero: nothing to add).
    /// add_torques : ndarray, shape (N, 3), float32
    ///     Torque to add, about the center of mass, N·m.
    /// wake : ndarray, shape (N,), bool
    ///     Whether to wake each body if it sleeps: the force or torque changed by more than
    ///     0.1 % since it was last awake, or it sleeps out of balance (then possibly with
    ///     nothing to add: wake it whenever this is True).
    ///
    /// Raises
    /// ------
    /// ValueError
    ///     Naming the argument (and the row) at fault: a shape other than the one above (with
    ///     ``N`` the number of bodies), values that cannot be converted, a non-unit quaternion,
    ///     negative or non-finite mass properties, a ``dt`` that is negative or not finite; a
    ///     water surface given as a callable that returned other than one finite elevation per
    ///     point (``water: waves: ...``).
    /// Exception
    ///     Whatever a water surface given as a callable raised.
    ///
    /// After any error nothing was applied and :attr:`time` did not advance.
    #[pyo3(
        signature = (dt, positions, quaternions, centers_of_mass, linear_velocities, angular_velocities, masses, inverse_masses, inverse_inertias, gravity_scales, applied_forces, applied_torques, dynamic, sleeping),
        text_signature = "(self, dt, positions, quaternions, centers_of_mass, linear_velocities, angular_velocities, masses, inverse_masses, inverse_inertias, gravity_scales, applied_forces, applied_torques, dynamic, sleeping)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn step<'py>(
        &self,
        py: Python<'py>,
        dt: &Bound<'py, PyAny>,
        positions: &Bound<'py, PyAny>,
        quaternions: &Bound<'py, PyAny>,
        centers_of_mass: &Bound<'py, PyAny>,
        linear_velocities: &Bound<'py, PyAny>,
        angular_velocities: &Bound<'py, PyAny>,
        masses: &Bound<'py, PyAny>,
        inverse_masses: &Bound<'py, PyAny>,
        inverse_inertias: &Bound<'py, PyAny>,
        gravity_scales: &Bound<'py, PyAny>,
        applied_forces: &Bound<'py, PyAny>,
        applied_torques: &Bound<'py, PyAny>,
        dynamic: &Bound<'py, PyAny>,
        sleeping: &Bound<'py, PyAny>,
    ) -> PyResult<StepResult<'py>> {
        let mut guard = self.lock(py)?;
        let this = &mut *guard;
        let dt = convert::real(dt, "dt")?;
        if !(dt.is_finite() && dt >= 0.0) {
            return Err(arg_error(
                "dt",
                format!("must be finite and non-negative (s), got {dt}"),
            ));
        }
        let n = this.inner.len();
        let row3: &[&[usize]] = &[&[3]];
        let scalar: &[&[usize]] = &[&[]];
        let vectors = "one 3-vector per body";
        let f64s = "float64";
        let positions = Input::<f64>::parse(positions, "positions", n, row3, f64s, vectors)?;
        let quaternions = Input::<f64>::parse(
            quaternions,
            "quaternions",
            n,
            &[&[4]],
            f64s,
            "one quaternion (x, y, z, w) per body",
        )?;
        let centers_of_mass =
            Input::<f64>::parse(centers_of_mass, "centers_of_mass", n, row3, f64s, vectors)?;
        let linear_velocities = Input::<f64>::parse(
            linear_velocities,
            "linear_velocities",
            n,
            row3,
            f64s,
            vectors,
        )?;
        let angular_velocities = Input::<f64>::parse(
            angular_velocities,
            "angular_velocities",
            n,
            row3,
            f64s,
            vectors,
        )?;
        let masses = Input::<f64>::parse(masses, "masses", n, scalar, f64s, "one mass per body")?;
        let inverse_masses = Input::<f64>::parse(
            inverse_masses,
            "inverse_masses",
            n,
            &[&[3], &[]],
            f64s,
            "per world axis, or one per body",
        )?;
        let inverse_inertias = Input::<f64>::parse(
            inverse_inertias,
            "inverse_inertias",
            n,
            &[&[3, 3]],
            f64s,
            "one 3×3 world inverse inertia tensor per body",
        )?;
        let gravity_scales = Input::<f64>::parse(
            gravity_scales,
            "gravity_scales",
            n,
            scalar,
            f64s,
            "one factor per body",
        )?;
        let applied_forces = Input::<f32>::parse(
            applied_forces,
            "applied_forces",
            n,
            row3,
            "float32",
            vectors,
        )?;
        let applied_torques = Input::<f32>::parse(
            applied_torques,
            "applied_torques",
            n,
            row3,
            "float32",
            vectors,
        )?;
        let dynamic =
            Input::<bool>::parse(dynamic, "dynamic", n, scalar, "bool", "one flag per body")?;
        let sleeping =
            Input::<bool>::parse(sleeping, "sleeping", n, scalar, "bool", "one flag per body")?;
        let columns = Columns {
            positions: positions.values(),
            quaternions: quaternions.values(),
            centers_of_mass: centers_of_mass.values(),
            linear_velocities: linear_velocities.values(),
            angular_velocities: angular_velocities.values(),
            masses: masses.values(),
            inverse_masses: inverse_masses.values(),
            inverse_masses_per_axis: inverse_masses.ndim() == 2,
            inverse_inertias: inverse_inertias.values(),
            gravity_scales: gravity_scales.values(),
            applied_forces: applied_forces.values(),
            applied_torques: applied_torques.values(),
            dynamic: dynamic.values(),
            sleeping: sleeping.values(),
        };
        // A Python surface may fail: the step is then undone, as if it had not been called.
        let function = this.sea.as_ref().and_then(|sea| sea.function.clone());
        let before = function.as_ref().map(|_| this.inner.clone());
        let (controller, states, commands) =
            (&mut this.inner, &mut this.states, &mut this.commands);
        py.detach(|| {
            columns.read(n, states)?;
            commands.resize(n, Command::default());
            controller.step(states, dt, commands);
            Ok(())
        })
        .map_err(|rejected: crate::step_inputs::Rejected| rejected.into_py())?;
        if let Some(failure) = function.and_then(|f| f.take_failure()) {
            if let Some(before) = before {
                this.inner = before;
            }
            return Err(Failure::Function(failure).into_py(Some("water")));
        }

        let mut forces = Vec::with_capacity(3 * n);
        let mut torques = Vec::with_capacity(3 * n);
        let mut wake = Vec::with_capacity(n);
        for c in commands.iter() {
            forces.extend_from_slice(c.add_force.as_slice());
            torques.extend_from_slice(c.add_torque.as_slice());
            wake.push(c.wake);
        }
        let rows = |flat: Vec<f32>| {
            Array2::from_shape_vec((n, 3), flat)
                .unwrap_or_else(|_| unreachable!("three values per body"))
                .into_pyarray(py)
        };
        Ok((rows(forces), rows(torques), PyArray1::from_vec(py, wake)))
    }
}
