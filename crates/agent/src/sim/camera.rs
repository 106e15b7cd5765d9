//! The simulated camera: a colour picture of the room from the robot's pose, as a JPEG.
//!
//! Design: one horizontal ray per image column, as early 3D games drew their rooms. The
//! ray ([`world::cast_2d`]) gives the distance to the wall and to a pillar in front of
//! it; perspective turns each distance into the rows that surface covers in that column,
//! and every other row is ceiling (above) or floor (below). The floor is a 1 m
//! checkerboard found per pixel from the row's depth, so motion shows; each wall has its
//! own tint, so the heading shows; light falls off with depth, and pillars are shaded by
//! the angle the ray meets them at, so they read as round.
//!
//! The picture is a pure function of the pose (no noise), like every simulated message a
//! pure function of its slot. It is drawn into a [`Canvas`] and encoded into a JPEG
//! buffer, both kept in [`super::messages::Scratch`] and reused frame to frame. Cost
//! matters (a demo runs three robots in one process): colours are worked out per column
//! and per row, never per pixel, so drawing is a small part of a frame and the JPEG
//! encoder the rest (docs/benchmarks.md, "Demo camera").

use jpeg_encoder::{ColorType, Encoder};

use super::world::{self, CEILING, HALF_ROOM, PILLAR_HEIGHT, PILLARS, RobotState};

/// Lens height above the floor, m. Below the pillars' tops, so they rise above the
/// horizon like objects in the room.
const CAMERA_HEIGHT: f64 = 1.0;
/// Horizontal field of view, radians (60°). Pixels are square, so the vertical one
/// follows from the aspect ratio.
const HORIZONTAL_FOV: f64 = std::f64::consts::FRAC_PI_3;
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

/// Reused between frames: the picture and what each column shows.
#[derive(Debug, Default)]
pub(crate) struct Canvas {
    /// Row-major RGB, 3 bytes a pixel.
    pub(crate) rgb: Vec<u8>,
    columns: Vec<Column>,
}

/// One image column: the rows each surface covers (first row of the next surface down)
/// and the constants its floor pixels need.
#[derive(Debug)]
struct Column {
    wall_top: usize,
    skirting_top: usize,
    wall_foot: usize,
    /// Rows `pillar.0..pillar.1` show a pillar (empty when the ray misses them all).
    pillar: (usize, usize),
    wall: [u8; 3],
    skirting: [u8; 3],
    pillar_colour: [u8; 3],
    /// Floor point at depth `d` along this column: `(x + ux·d, y + uy·d)`.
    ux: f64,
    uy: f64,
}

/// Draws the room as seen from `state` into `canvas.rgb`, resized to the frame.
///
/// Two passes: one ray per column finds which rows show what, then the pixels are written
/// row by row, where the floor's depth and shade are the same along a row.
pub(crate) fn render(canvas: &mut Canvas, spec: CameraSpec, state: &RobotState) {
    let (width, height) = (usize::from(spec.width), usize::from(spec.height));
    let focal = spec.focal();
    let (mid_x, mid_y) = (width as f64 / 2.0, height as f64 / 2.0);
    // Image row (continuous, from the top) of height `z` on a surface `depth` m ahead
    // (along the optical axis, so straight walls stay straight), and the first whole row
    // whose centre is below it.
    let row_of = |z: f64, depth: f64| mid_y - (z - CAMERA_HEIGHT) / depth * focal;
    let first_row_below = |edge: f64| (edge - 0.5).ceil().clamp(0.0, height as f64) as usize;
    canvas.columns.clear();
    canvas.columns.extend((0..width).map(|col| {
        // This column's ray, off the optical axis by `off`; columns left of centre look
        // left (counter-clockwise, positive yaw).
        let off = ((mid_x - col as f64 - 0.5) / focal).atan();
        let cos_off = off.cos();
        let (dy, dx) = (state.yaw + off).sin_cos();
        let (wall_t, pillar_t) = world::cast_2d(state.x, state.y, dx, dy);
        let depth = wall_t * cos_off;
        let (pillar, pillar_colour) = pillar_t.map_or(((0, 0), [0; 3]), |t| {
            let depth = t * cos_off;
            let rows = (
                first_row_below(row_of(PILLAR_HEIGHT, depth)),
                first_row_below(row_of(0.0, depth)),
            );
            (
                rows,
                pillar_colour(state.x + dx * t, state.y + dy * t, dx, dy, depth),
            )
        });
        Column {
            wall_top: first_row_below(row_of(CEILING, depth)),
            skirting_top: first_row_below(row_of(SKIRTING, depth)),
            wall_foot: first_row_below(row_of(0.0, depth)),
            pillar,
            wall: wall_colour(state.x + dx * wall_t, state.y + dy * wall_t, depth),
            skirting: to_bytes(shade(SKIRTING_COLOUR, depth)),
            pillar_colour,
            ux: dx / cos_off,
            uy: dy / cos_off,
        }
    }));
    canvas.rgb.resize(width * height * 3, 0);
    for (row, pixels) in canvas.rgb.chunks_exact_mut(width * 3).enumerate() {
        let y = row as f64 + 0.5;
        let ceiling = to_bytes(ceiling_colour(y / mid_y));
        // The floor this row sees lies `depth` m ahead: from the row's angle below the
        // horizon (rows above it never show floor).
        let depth = if y > mid_y {
            CAMERA_HEIGHT * focal / (y - mid_y)
        } else {
            f64::INFINITY
        };
        let tiles = floor_colours(depth);
        for (c, pixel) in canvas.columns.iter().zip(pixels.chunks_exact_mut(3)) {
            let colour = if (c.pillar.0..c.pillar.1).contains(&row) {
                c.pillar_colour
            } else if row < c.wall_top {
                ceiling
            } else if row < c.skirting_top {
                c.wall
            } else if row < c.wall_foot {
                c.skirting
            } else {
                // Tile parity of the floor point. The floor seen is inside the 20 m
                // room, so the offset keeps its coordinates positive (truncation is then
                // floor), and it is a whole even number of tiles, so parity is kept.
                let tx = (state.x + c.ux * depth + 64.0 * TILE) / TILE;
                let ty = (state.y + c.uy * depth + 64.0 * TILE) / TILE;
                tiles[((tx as i64 + ty as i64) & 1) as usize]
            };
            pixel.copy_from_slice(&colour);
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

/// Light falls off with depth `d` (m), to a third at the room's far corner.
#[inline]
fn shade(c: Rgb, d: f64) -> Rgb {
    let k = (1.0 / (1.0 + 0.07 * d)) as f32;
    c.map(|v| v * k)
}

fn to_bytes(c: Rgb) -> [u8; 3] {
    c.map(|v| v.clamp(0.0, 255.0) as u8)
}

/// The wall at hit point `(x, y)`, `d` m deep: its side's tint, with a darker seam every
/// [`WALL_PANEL`] m along it.
fn wall_colour(x: f64, y: f64, d: f64) -> [u8; 3] {
    // The wall hit is the one the point is nearest to.
    let (tint, along, side_light) = if HALF_ROOM - x.abs() < HALF_ROOM - y.abs() {
        (if x > 0.0 { WALL_EAST } else { WALL_WEST }, y, 1.0)
    } else {
        (if y > 0.0 { WALL_NORTH } else { WALL_SOUTH }, x, 0.85)
    };
    let panel = (along / WALL_PANEL).rem_euclid(1.0);
    let seam = if (0.01..=0.99).contains(&panel) {
        1.0
    } else {
        0.6
    };
    to_bytes(shade(tint.map(|v| v * side_light * seam), d))
}

/// A pillar hit at `(x, y)` by a ray in direction `(dx, dy)`, `d` m deep: brightest where
/// the ray meets its surface head on.
fn pillar_colour(x: f64, y: f64, dx: f64, dy: f64, d: f64) -> [u8; 3] {
    // The pillar hit is the one whose surface the point is on (nearest to).
    let gap = |&(cx, cy, r): &(f64, f64, f64)| ((x - cx).hypot(y - cy) - r).abs();
    let Some(&(cx, cy, r)) = PILLARS.iter().min_by(|a, b| gap(a).total_cmp(&gap(b))) else {
        return to_bytes(shade(PILLAR, d));
    };
    let facing = (-((x - cx) * dx + (y - cy) * dy) / r).clamp(0.0, 1.0);
    to_bytes(shade(PILLAR.map(|v| v * (0.35 + 0.65 * facing as f32)), d))
}

/// The ceiling, lighter overhead than towards the horizon; `down` is 0 at the picture's
/// top edge and 1 at the horizon.
#[inline]
fn ceiling_colour(down: f64) -> Rgb {
    let near = (1.0 - down).clamp(0.0, 1.0) as f32;
    std::array::from_fn(|i| CEILING_FAR[i] + (CEILING_NEAR[i] - CEILING_FAR[i]) * near)
}

/// The floor's two tile colours `d` m deep, dark then light: their contrast fades with
/// depth, so the far floor does not shimmer between tiles smaller than a pixel.
fn floor_colours(d: f64) -> [[u8; 3]; 2] {
    if !d.is_finite() {
        return [[0; 3]; 2];
    }
    let contrast = (1.0 / (1.0 + 0.15 * d * d / TILE)) as f32;
    [FLOOR_DARK, FLOOR_LIGHT].map(|base| {
        let c: Rgb = std::array::from_fn(|i| {
            let mid = (FLOOR_LIGHT[i] + FLOOR_DARK[i]) / 2.0;
            mid + (base[i] - mid) * contrast
        });
        to_bytes(shade(c, d))
    })
}
