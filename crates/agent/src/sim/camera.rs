//! The simulated camera: a colour picture of the room from the robot's pose, as a JPEG.
//!
//! Design: one horizontal ray per image column, as early 3D games drew their rooms. The
//! ray ([`world::cast_2d`]) gives the distance to the wall and to a pillar in front of
//! it; perspective turns each distance into the rows that surface covers in that column,
//! and every other row is ceiling (above) or floor (below). The floor is a 1 m
//! checkerboard found per pixel from the row's depth, so motion shows; each wall has its
//! own tint, so the heading shows; light falls off with distance, and pillars are shaded by
//! the angle the ray meets them at, so they read as round.
//!
//! The picture is a pure function of the pose (no noise), like every simulated message a
//! pure function of its slot. It is drawn into an RGB buffer and encoded into a JPEG
//! buffer that both live in [`super::messages::Scratch`] and are reused frame to frame.

use jpeg_encoder::{ColorType, Encoder};

use super::world::{self, CEILING, HALF_ROOM, PILLAR_HEIGHT, PILLARS, RobotState};

/// Lens height above the floor, m. Below the pillars' tops, so they rise above the
/// horizon like objects in the room.
pub(crate) const CAMERA_HEIGHT: f64 = 1.0;
/// Horizontal field of view, radians (60°). Pixels are square, so the vertical one
/// follows from the aspect ratio.
pub(crate) const HORIZONTAL_FOV: f64 = std::f64::consts::FRAC_PI_3;
/// Floor tile size, m.
const TILE: f64 = 1.0;
/// Spacing of the seams drawn on the walls, m.
const WALL_PANEL: f64 = 2.0;
/// Height of the dark skirting board along the walls' foot, m.
const SKIRTING: f64 = 0.15;

type Rgb = [f32; 3];

/// Wall tints by side, so the picture tells which way the robot looks.
const WALL_EAST: Rgb = [150.0, 180.0, 225.0]; // x = +10: blue
const WALL_WEST: Rgb = [225.0, 200.0, 140.0]; // x = -10: sand
const WALL_NORTH: Rgb = [160.0, 210.0, 160.0]; // y = +10: green
const WALL_SOUTH: Rgb = [220.0, 160.0, 170.0]; // y = -10: rose
const SKIRTING_COLOUR: Rgb = [70.0, 62.0, 56.0];
const PILLAR: Rgb = [235.0, 120.0, 30.0];
const CEILING_NEAR: Rgb = [236.0, 236.0, 232.0];
const CEILING_FAR: Rgb = [200.0, 202.0, 206.0];
const FLOOR_DARK: Rgb = [92.0, 88.0, 84.0];
const FLOOR_LIGHT: Rgb = [150.0, 146.0, 138.0];

/// What one camera frame looks like, from the `sim.image` config.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct CameraSpec {
    pub(crate) width: u16,
    pub(crate) height: u16,
    pub(crate) quality: u8,
}

impl CameraSpec {
    /// Clamped to what the encoder takes (validation keeps loaded configs in range; this
    /// covers configs built in code).
    pub(crate) fn new(width: u32, height: u32, quality: u32) -> Self {
        let side = |v: u32| u16::try_from(v.max(1)).unwrap_or(u16::MAX);
        Self {
            width: side(width),
            height: side(height),
            quality: u8::try_from(quality.clamp(1, 100)).unwrap_or(100),
        }
    }

    /// Focal length in pixels.
    pub(crate) fn focal(self) -> f64 {
        f64::from(self.width) / 2.0 / (HORIZONTAL_FOV / 2.0).tan()
    }
}

/// Draws the room as seen from `state` into `rgb` (row-major, 3 bytes a pixel), resized to
/// the frame; the allocation is kept between frames.
pub(crate) fn render(rgb: &mut Vec<u8>, spec: CameraSpec, state: &RobotState) {
    let (width, height) = (usize::from(spec.width), usize::from(spec.height));
    rgb.resize(width * height * 3, 0);
    let focal = spec.focal();
    let (mid_x, mid_y) = (width as f64 / 2.0, height as f64 / 2.0);
    for col in 0..width {
        // Angle of this column's ray off the optical axis; columns left of centre look left
        // (counter-clockwise, positive yaw).
        let off = ((mid_x - col as f64 - 0.5) / focal).atan();
        let cos_off = off.cos();
        let (dy, dx) = (state.yaw + off).sin_cos();
        let (wall_t, pillar_t) = world::cast_2d(state.x, state.y, dx, dy);
        // Depth along the optical axis, not along the ray, so straight walls stay straight.
        let wall_depth = wall_t * cos_off;
        let wall = wall_colour(state.x + dx * wall_t, state.y + dy * wall_t, wall_t);
        // Image rows (continuous, from the top) of a height `z` on a surface at `depth`.
        let row_of = |z: f64, depth: f64| mid_y - (z - CAMERA_HEIGHT) / depth * focal;
        let wall_top = row_of(CEILING, wall_depth);
        let wall_foot = row_of(0.0, wall_depth);
        let skirting_top = row_of(SKIRTING, wall_depth);
        let pillar = pillar_t.map(|t| {
            let depth = t * cos_off;
            (
                row_of(PILLAR_HEIGHT, depth),
                row_of(0.0, depth),
                pillar_colour(state.x + dx * t, state.y + dy * t, dx, dy, t),
            )
        });
        for row in 0..height {
            let y = row as f64 + 0.5;
            let colour = match pillar {
                Some((top, foot, c)) if (top..foot).contains(&y) => c,
                _ if y < wall_top => ceiling_colour(y / mid_y),
                _ if y < skirting_top => wall,
                _ if y < wall_foot => shade(SKIRTING_COLOUR, wall_t),
                _ => {
                    // The floor point this pixel sees: depth from the row's angle below the
                    // horizon, then along this column's ray.
                    let along = CAMERA_HEIGHT * focal / (y - mid_y) / cos_off;
                    floor_colour(state.x + dx * along, state.y + dy * along, along)
                }
            };
            let at = (row * width + col) * 3;
            for (byte, v) in rgb[at..at + 3].iter_mut().zip(colour) {
                *byte = v.clamp(0.0, 255.0) as u8;
            }
        }
    }
}

/// Encodes the `rgb` frame as a baseline JPEG into `out` (cleared first; its allocation
/// is kept between frames).
pub(crate) fn encode(rgb: &[u8], spec: CameraSpec, out: &mut Vec<u8>) {
    out.clear();
    let encoder = Encoder::new(&mut *out, spec.quality);
    // The only failures are a zero-sized frame or too few bytes for its size; `CameraSpec`
    // and `render` rule both out.
    if let Err(e) = encoder.encode(rgb, spec.width, spec.height, ColorType::Rgb) {
        unreachable!("encoding a simulated camera frame failed: {e}");
    }
}

/// Light falls off with distance `d` (m), to a third at the room's far corner.
#[inline]
fn shade(c: Rgb, d: f64) -> Rgb {
    let k = (1.0 / (1.0 + 0.07 * d)) as f32;
    c.map(|v| v * k)
}

/// The wall at hit point `(x, y)`, `d` m away: its side's tint, with a darker seam every
/// [`WALL_PANEL`] m along it.
fn wall_colour(x: f64, y: f64, d: f64) -> Rgb {
    // The wall hit is the one the point is nearest to.
    let (tint, along, side_light) = if HALF_ROOM - x.abs() < HALF_ROOM - y.abs() {
        (if x > 0.0 { WALL_EAST } else { WALL_WEST }, y, 1.0)
    } else {
        (if y > 0.0 { WALL_NORTH } else { WALL_SOUTH }, x, 0.85)
    };
    let panel = (along / WALL_PANEL).rem_euclid(1.0);
    let seam = if !(0.01..=0.99).contains(&panel) {
        0.6
    } else {
        1.0
    };
    shade(tint.map(|v| v * side_light * seam), d)
}

/// A pillar hit at `(x, y)` by a ray in direction `(dx, dy)`, `d` m away: brightest where
/// the ray meets its surface head on.
fn pillar_colour(x: f64, y: f64, dx: f64, dy: f64, d: f64) -> Rgb {
    let Some(&(cx, cy, r)) = PILLARS.iter().min_by(|a, b| {
        let da = (x - a.0).hypot(y - a.1) - a.2;
        let db = (x - b.0).hypot(y - b.1) - b.2;
        da.abs().total_cmp(&db.abs())
    }) else {
        return shade(PILLAR, d);
    };
    let facing = (-((x - cx) * dx + (y - cy) * dy) / r).clamp(0.0, 1.0);
    shade(PILLAR.map(|v| v * (0.35 + 0.65 * facing as f32)), d)
}

/// The ceiling, lighter overhead than towards the horizon; `down` is 0 at the picture's
/// top edge and 1 at the horizon.
#[inline]
fn ceiling_colour(down: f64) -> Rgb {
    let near = (1.0 - down).clamp(0.0, 1.0) as f32;
    std::array::from_fn(|i| CEILING_FAR[i] + (CEILING_NEAR[i] - CEILING_FAR[i]) * near)
}

/// The floor at `(x, y)`, `d` m away: 1 m tiles whose contrast fades with distance, so the
/// far floor does not shimmer between tiles smaller than a pixel.
#[inline]
fn floor_colour(x: f64, y: f64, d: f64) -> Rgb {
    let light = ((x / TILE).floor() + (y / TILE).floor()).rem_euclid(2.0) > 0.5;
    let contrast = (1.0 / (1.0 + 0.15 * d * d / TILE)) as f32;
    let base = if light { FLOOR_LIGHT } else { FLOOR_DARK };
    let c: Rgb = std::array::from_fn(|i| {
        let mid = (FLOOR_LIGHT[i] + FLOOR_DARK[i]) / 2.0;
        mid + (base[i] - mid) * contrast
    });
    shade(c, d)
}
