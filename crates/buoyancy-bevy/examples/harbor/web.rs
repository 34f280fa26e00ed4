//! The harbor in a web page (`wasm32-unknown-unknown`, feature `web`): the page's controls in,
//! a report out.
//!
//! The page (`web/index.html`) fetches the bunny's OBJ into `window.harborBunny` before the
//! module starts, and keeps its sliders in `window.harborControls`:
//! `{hs, tp, direction, densities: [kg/m³ per body]}`, read here every frame. Once a second the
//! harbor writes `window.harborReport` and logs it on the console as one line, `HARBOR {json}`:
//! the physics time; over the last second, the mean frame time (the page's clock), the time a
//! frame of its fixed 60 Hz steps (bevy_rapier's with the buoyancy plugin's), their number and
//! their mean; and each body's height, draft and theoretical draft in calm water.

use bevy::platform::time::Instant;
use bevy::prelude::*;
use buoyancy_bevy::{FloatReport, Water};
use js_sys::Reflect;
use wasm_bindgen::JsValue;

use crate::render::{SeaControls, set_sea};
use crate::scene::HarborBody;
use crate::{Harbor, Sea};

/// The bunny's OBJ text the page fetched, if it did.
pub fn bunny_obj() -> Option<String> {
    Reflect::get(&js_sys::global(), &JsValue::from_str("harborBunny"))
        .ok()
        .and_then(|v| v.as_string())
}

/// The sea of `window.harborControls` (the page sets it from its query string and its sliders),
/// over `sea`.
pub fn page_sea(mut sea: Sea) -> Sea {
    if let Some(hs) = control("hs") {
        sea.significant_height = hs.clamp(0.0, 3.0);
    }
    if let Some(tp) = control("tp") {
        sea.peak_period = tp.clamp(2.0, 12.0);
    }
    if let Some(direction) = control("direction") {
        sea.direction_degrees = direction;
    }
    sea
}

/// A finite number of `window.harborControls`.
fn control(key: &str) -> Option<f64> {
    let controls = Reflect::get(&js_sys::global(), &JsValue::from_str("harborControls")).ok()?;
    Reflect::get(&controls, &JsValue::from_str(key))
        .ok()?
        .as_f64()
        .filter(|v| v.is_finite())
}

/// The densities of `window.harborControls.densities`, kg/m³, by body.
fn densities() -> Vec<Option<f64>> {
    let Some(list) = Reflect::get(&js_sys::global(), &JsValue::from_str("harborControls"))
        .ok()
        .and_then(|c| Reflect::get(&c, &JsValue::from_str("densities")).ok())
        .filter(|l| l.is_object())
    else {
        return Vec::new();
    };
    let array = js_sys::Array::from(&list);
    array
        .iter()
        .map(|v| v.as_f64().filter(|d| d.is_finite() && *d > 0.0))
        .collect()
}

/// What the report averages over a second.
#[derive(Resource, Default)]
struct Timing {
    since: Option<Instant>,
    frames: u32,
    physics_seconds: f64,
    physics_started: Option<Instant>,
    steps: u32,
}

/// The densities the bodies have now, kg/m³ (the page's, once applied).
#[derive(Resource, Default)]
struct Densities(Vec<f64>);

/// Adds the page's controls and report to the windowed harbor.
///
/// The physics clock runs around the frame's fixed steps (`RunFixedMainLoop`): bevy_rapier's
/// steps with the buoyancy plugin's, as many as the frame lasted at 60 Hz. One clock a frame
/// rather than one a step, as the page's clock ticks in 0.1 ms.
pub fn add(app: &mut App) {
    use bevy::app::{RunFixedMainLoop, RunFixedMainLoopSystems};
    app.init_resource::<Timing>()
        .init_resource::<Densities>()
        .add_systems(Update, (follow_the_sea, follow_the_densities))
        .add_systems(
            RunFixedMainLoop,
            (
                start_physics_clock.in_set(RunFixedMainLoopSystems::BeforeFixedMainLoop),
                stop_physics_clock.in_set(RunFixedMainLoopSystems::AfterFixedMainLoop),
            ),
        )
        .add_systems(FixedUpdate, count_the_step)
        .add_systems(Last, report);
}

fn follow_the_sea(mut controls: ResMut<SeaControls>, mut water: ResMut<Water>) {
    let sea = page_sea(controls.0);
    set_sea(sea, &mut controls, &mut water);
}

/// Gives each body the page's density: its mass (and inertia) scaled, its center of mass kept.
fn follow_the_densities(
    harbor: Res<Harbor>,
    mut current: ResMut<Densities>,
    mut bodies: Query<(
        &HarborBody,
        &mut bevy_rapier3d::prelude::ColliderMassProperties,
    )>,
) {
    if current.0.is_empty() {
        current.0 = harbor.bodies.iter().map(|b| b.mean_density()).collect();
    }
    let wanted = densities();
    for (HarborBody(i), mut mass) in &mut bodies {
        let Some(Some(density)) = wanted.get(*i).copied() else {
            continue;
        };
        if density == current.0[*i] {
            continue;
        }
        let body = &harbor.bodies[*i];
        let factor = (density / body.mean_density()) as f32;
        *mass = crate::rapier_mass(&body.mass, factor);
        current.0[*i] = density;
    }
}

fn count_the_step(mut timing: ResMut<Timing>) {
    timing.steps += 1;
}

fn start_physics_clock(mut timing: ResMut<Timing>) {
    timing.physics_started = Some(Instant::now());
}

fn stop_physics_clock(mut timing: ResMut<Timing>) {
    if let Some(started) = timing.physics_started.take() {
        timing.physics_seconds += started.elapsed().as_secs_f64();
    }
}

/// Once a second: `window.harborReport` and the console line `HARBOR {json}`.
fn report(
    mut timing: ResMut<Timing>,
    water: Res<Water>,
    harbor: Res<Harbor>,
    densities: Res<Densities>,
    controls: Res<SeaControls>,
    bodies: Query<(&HarborBody, &Transform, &FloatReport)>,
) {
    timing.frames += 1;
    let since = *timing.since.get_or_insert_with(Instant::now);
    // The page's clock, not Bevy's delta (which stops at 0.25 s a frame).
    let wall_seconds = since.elapsed().as_secs_f64();
    if wall_seconds < 1.0 {
        return;
    }
    let frames = f64::from(timing.frames.max(1));
    let mut rows: Vec<(usize, String)> = bodies
        .iter()
        .map(|(HarborBody(i), transform, report)| {
            let body = &harbor.bodies[*i];
            let density = densities.0.get(*i).copied().unwrap_or(body.mean_density());
            // The theory holds for the scene's own densities.
            let theory = if (density - body.mean_density()).abs() <= 1e-9 * density {
                format!("{:.5}", body.draft)
            } else {
                "null".into()
            };
            (
                *i,
                format!(
                    "{{\"name\":\"{}\",\"height\":{},\"draft\":{},\"theory\":{theory},\"density\":{:.1},\"error\":{}}}",
                    body.name,
                    json_number(f64::from(transform.translation.y)),
                    json_number(report.draft),
                    density,
                    report
                        .error
                        .as_ref()
                        .map_or("null".into(), |e| format!("{e:?}")),
                ),
            )
        })
        .collect();
    rows.sort_by_key(|(i, _)| *i);
    let line = format!(
        "{{\"time\":{:.3},\"hs\":{:.2},\"frame_ms\":{:.2},\"physics_ms\":{:.3},\"steps\":{},\"step_ms\":{:.3},\"bodies\":[{}]}}",
        water.time(),
        controls.0.significant_height,
        1e3 * wall_seconds / frames,
        1e3 * timing.physics_seconds / frames,
        timing.steps,
        1e3 * timing.physics_seconds / f64::from(timing.steps.max(1)),
        rows.into_iter()
            .map(|(_, r)| r)
            .collect::<Vec<_>>()
            .join(",")
    );
    let _ = Reflect::set(
        &js_sys::global(),
        &JsValue::from_str("harborReport"),
        &JsValue::from_str(&line),
    );
    web_sys::console::log_1(&JsValue::from_str(&format!("HARBOR {line}")));
    *timing = Timing::default();
}

/// A JSON number, or `null` when not finite (the check then fails on it).
fn json_number(value: f64) -> String {
    if value.is_finite() {
        format!("{value:.5}")
    } else {
        "null".into()
    }
}
