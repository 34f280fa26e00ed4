//! The harbor's window: the bodies drawn from the meshes they float with, the water drawn from
//! [`Water::elevation`] (the surface the bodies feel) each frame, a camera, a light, an overlay
//! and keys that change the sea.

use bevy::asset::RenderAssetUsages;
use bevy::mesh::{Indices, PrimitiveTopology};
use bevy::prelude::*;
#[cfg(feature = "render")]
use buoyancy_bevy::FloatReport;
use buoyancy_bevy::Water;
use buoyancy_core::Mesh as CoreMesh;

use crate::scene::HarborBody;
use crate::{Harbor, Sea};

/// Half the side of the square of water drawn, m.
const WATER_HALF_SIDE: f32 = 24.0;
/// Cells along each side of the water mesh.
const WATER_CELLS: usize = 96;

/// The sea the keys set; the waves are rebuilt when it changes.
#[derive(Resource, Clone, Copy)]
pub struct SeaControls(pub Sea);

/// The water's mesh.
#[derive(Resource)]
struct WaterMesh(Handle<Mesh>);

/// The overlay's text (the page writes its own, in HTML).
#[cfg(feature = "render")]
#[derive(Component)]
struct Overlay;

/// Adds the window, the renderer and the harbor's drawing to `app`, with the sea `sea`.
pub fn add(app: &mut App, sea: Sea) {
    app.add_plugins(DefaultPlugins.set(WindowPlugin {
        primary_window: Some(Window {
            title: "buoyancy: the harbor".into(),
            canvas: Some("#harbor".into()),
            fit_canvas_to_parent: true,
            ..default()
        }),
        ..default()
    }))
    .insert_resource(ClearColor(Color::srgb(0.62, 0.75, 0.86)))
    .insert_resource(SeaControls(sea))
    .add_systems(Startup, setup)
    .add_systems(
        Update,
        (
            dress_bodies,
            steer_the_sea,
            draw_the_water,
            #[cfg(feature = "render")]
            write_the_overlay,
        ),
    );
}

/// A Bevy mesh of a core mesh, flat shaded.
fn bevy_mesh(mesh: &CoreMesh<f64>) -> Mesh {
    let positions: Vec<[f32; 3]> = (0..mesh.vertex_count())
        .map(|i| {
            let p = mesh.vertex(i);
            [p.x as f32, p.y as f32, p.z as f32]
        })
        .collect();
    let indices: Vec<u32> = mesh.triangles().iter().flatten().copied().collect();
    let mut out = Mesh::new(
        PrimitiveTopology::TriangleList,
        RenderAssetUsages::default(),
    );
    out.insert_attribute(Mesh::ATTRIBUTE_POSITION, positions);
    out.insert_indices(Indices::U32(indices));
    out.duplicate_vertices();
    out.compute_flat_normals();
    out
}

/// The water grid: positions at the still level, indices, normals up.
fn water_grid() -> Mesh {
    let n = WATER_CELLS + 1;
    let step = 2.0 * WATER_HALF_SIDE / WATER_CELLS as f32;
    let mut positions = Vec::with_capacity(n * n);
    for row in 0..n {
        for column in 0..n {
            positions.push([
                -WATER_HALF_SIDE + column as f32 * step,
                0.0,
                -WATER_HALF_SIDE + row as f32 * step,
            ]);
        }
    }
    let mut indices = Vec::with_capacity(6 * WATER_CELLS * WATER_CELLS);
    for row in 0..WATER_CELLS {
        for column in 0..WATER_CELLS {
            let a = (row * n + column) as u32;
            let (b, c, d) = (a + 1, a + n as u32, a + n as u32 + 1);
            indices.extend_from_slice(&[a, c, b, b, c, d]);
        }
    }
    let mut mesh = Mesh::new(
        PrimitiveTopology::TriangleList,
        RenderAssetUsages::default(),
    );
    mesh.insert_attribute(Mesh::ATTRIBUTE_NORMAL, vec![[0.0f32, 1.0, 0.0]; n * n]);
    mesh.insert_attribute(Mesh::ATTRIBUTE_POSITION, positions);
    mesh.insert_indices(Indices::U32(indices));
    mesh
}

fn setup(
    mut commands: Commands,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    let mut camera = commands.spawn((
        Camera3d::default(),
        Transform::from_xyz(-9.0, 7.0, 13.0).looking_at(Vec3::new(0.0, 0.0, 0.0), Vec3::Y),
    ));
    // The page goes without the tone-mapping tables (megabytes of wasm): a tone curve without
    // them.
    #[cfg(not(feature = "render"))]
    camera.insert(bevy::core_pipeline::tonemapping::Tonemapping::AcesFitted);
    #[cfg(feature = "render")]
    let _ = &mut camera;
    commands.spawn((
        DirectionalLight {
            illuminance: 9000.0,
            shadow_maps_enabled: false,
            ..default()
        },
        Transform::from_xyz(4.0, 10.0, 6.0).looking_at(Vec3::ZERO, Vec3::Y),
    ));
    let water = meshes.add(water_grid());
    commands.spawn((
        Mesh3d(water.clone()),
        MeshMaterial3d(materials.add(StandardMaterial {
            base_color: Color::srgba(0.05, 0.3, 0.45, 0.82),
            perceptual_roughness: 0.25,
            alpha_mode: AlphaMode::Blend,
            double_sided: true,
            cull_mode: None,
            ..default()
        })),
        Transform::default(),
    ));
    commands.insert_resource(WaterMesh(water));
    #[cfg(feature = "render")]
    commands.spawn((
        Text::new(""),
        TextFont {
            font_size: FontSize::Px(15.0),
            ..default()
        },
        TextColor(Color::srgb(0.05, 0.1, 0.15)),
        Node {
            position_type: PositionType::Absolute,
            top: Val::Px(10.0),
            left: Val::Px(12.0),
            ..default()
        },
        Overlay,
    ));
}

/// Gives each new harbor body the mesh it floats with, to draw.
fn dress_bodies(
    mut commands: Commands,
    new: Query<(Entity, &HarborBody), Added<HarborBody>>,
    harbor: Res<Harbor>,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    for (entity, HarborBody(i)) in &new {
        let body = &harbor.bodies[*i];
        let [r, g, b] = body.color;
        commands.entity(entity).insert((
            Mesh3d(meshes.add(bevy_mesh(&body.mesh))),
            MeshMaterial3d(materials.add(StandardMaterial {
                base_color: Color::srgb(r, g, b),
                perceptual_roughness: 0.7,
                ..default()
            })),
        ));
    }
}

/// Keys: ↑/↓ significant height ±0.1 m, ←/→ peak period ∓0.5 s, Q/E direction ∓15°, C calm,
/// S seed.
fn steer_the_sea(
    keys: Res<ButtonInput<KeyCode>>,
    mut controls: ResMut<SeaControls>,
    mut water: ResMut<Water>,
) {
    let mut sea = controls.0;
    if keys.just_pressed(KeyCode::ArrowUp) {
        sea.significant_height = (sea.significant_height + 0.1).min(3.0);
    }
    if keys.just_pressed(KeyCode::ArrowDown) {
        sea.significant_height = (sea.significant_height - 0.1).max(0.0);
    }
    if keys.just_pressed(KeyCode::ArrowRight) {
        sea.peak_period = (sea.peak_period + 0.5).min(12.0);
    }
    if keys.just_pressed(KeyCode::ArrowLeft) {
        sea.peak_period = (sea.peak_period - 0.5).max(2.0);
    }
    if keys.just_pressed(KeyCode::KeyQ) {
        sea.direction_degrees -= 15.0;
    }
    if keys.just_pressed(KeyCode::KeyE) {
        sea.direction_degrees += 15.0;
    }
    if keys.just_pressed(KeyCode::KeyC) {
        sea.significant_height = 0.0;
    }
    if keys.just_pressed(KeyCode::KeyS) {
        sea.seed += 1;
    }
    set_sea(sea, &mut controls, &mut water);
}

/// Makes `sea` the water's waves if it differs from the controls' (logging an error, and
/// keeping the old waves, if it cannot be built).
pub fn set_sea(sea: Sea, controls: &mut SeaControls, water: &mut Water) {
    if sea == controls.0 {
        return;
    }
    match sea.waves(water.density) {
        Ok(waves) => {
            water.set_waves(waves.map(|w| std::sync::Arc::new(w) as _));
            controls.0 = sea;
        }
        Err(e) => error!("harbor: cannot build that sea: {e}"),
    }
}

/// Moves the water mesh's vertices to the surface the bodies feel now.
fn draw_the_water(water: Res<Water>, handle: Res<WaterMesh>, mut meshes: ResMut<Assets<Mesh>>) {
    let Some(mut mesh) = meshes.get_mut(&handle.0) else {
        return;
    };
    let n = WATER_CELLS + 1;
    let step = 2.0 * WATER_HALF_SIDE / WATER_CELLS as f32;
    let mut positions = Vec::with_capacity(n * n);
    let mut normals = Vec::with_capacity(n * n);
    for row in 0..n {
        for column in 0..n {
            let x = -WATER_HALF_SIDE + column as f32 * step;
            let z = -WATER_HALF_SIDE + row as f32 * step;
            positions.push([x, water.elevation(x, z), z]);
            normals.push(water.normal(x, z).to_array());
        }
    }
    mesh.insert_attribute(Mesh::ATTRIBUTE_POSITION, positions);
    mesh.insert_attribute(Mesh::ATTRIBUTE_NORMAL, normals);
}

#[cfg(feature = "render")]
fn write_the_overlay(
    controls: Res<SeaControls>,
    water: Res<Water>,
    harbor: Res<Harbor>,
    bodies: Query<(&HarborBody, &FloatReport)>,
    time: Res<Time>,
    mut overlay: Query<&mut Text, With<Overlay>>,
) {
    let Ok(mut text) = overlay.single_mut() else {
        return;
    };
    let sea = controls.0;
    let mut lines = vec![
        format!(
            "buoyancy harbor on {:?}: t = {:.1} s, frame {:.1} ms",
            harbor.backend,
            water.time(),
            1e3 * time.delta_secs()
        ),
        if sea.significant_height > 0.0 {
            format!(
                "JONSWAP sea: Hs {:.1} m (up/down), Tp {:.1} s (left/right), towards {:.0} deg (Q/E), seed {} (S); C: calm",
                sea.significant_height, sea.peak_period, sea.direction_degrees, sea.seed
            )
        } else {
            "calm water (up: waves)".to_string()
        },
    ];
    let mut rows: Vec<(usize, String)> = bodies
        .iter()
        .map(|(HarborBody(i), report)| {
            let body = &harbor.bodies[*i];
            (
                *i,
                format!(
                    "{}: draft {:.3} m (calm water: {:.3} m), {:.0} % wetted",
                    body.name,
                    report.draft,
                    body.draft,
                    100.0 * report.wetted_fraction
                ),
            )
        })
        .collect();
    rows.sort_by_key(|(i, _)| *i);
    lines.extend(rows.into_iter().map(|(_, row)| row));
    text.0 = lines.join("\n");
}
