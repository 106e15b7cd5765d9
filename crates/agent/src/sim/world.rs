//! The simulated world: a 20 m × 20 m × 3 m room with round pillars, a robot driving a
//! figure-eight through it, and ray casting against both.
//!
//! Design: everything is a closed-form function of time (no integration state), so a
//! message is a pure function of (seed, robot name, time) and a driver that polls late
//! gets the same data as one that polls on time. Noise comes from a counter-based
//! generator seeded per message for the same reason.

use std::f64::consts::TAU;

/// Walls at x = ±HALF_ROOM and y = ±HALF_ROOM.
pub(crate) const HALF_ROOM: f64 = 10.0;
pub(crate) const CEILING: f64 = 3.0;
/// Pillars are shorter than the room so a 3D scan shows them as objects, not walls.
pub(crate) const PILLAR_HEIGHT: f64 = 1.5;

/// Round pillars `(x, y, radius)`, placed clear of the robot's path.
pub(crate) const PILLARS: [(f64, f64, f64); 5] = [
    (4.2, 0.0, 0.5),
    (-4.2, 0.0, 0.5),
    (0.0, 7.0, 0.8),
    (2.0, -7.5, 0.6),
    (8.8, 6.0, 0.5),
];

/// Figure-eight (lemniscate of Gerono) `x = A sin θ, y = B sin θ cos θ`, θ = θ0 + Ω t:
/// smooth position, heading, speed and turn rate; speed between 0.5 and 1.06 m/s.
const PATH_A: f64 = 7.0;
const PATH_B: f64 = 8.0;
const PATH_OMEGA: f64 = 0.1;

/// Where the robot is and how it moves, in the room (= `odom`) frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct RobotState {
    pub(crate) x: f64,
    pub(crate) y: f64,
    pub(crate) yaw: f64,
    /// Forward speed, m/s (body frame x).
    pub(crate) speed: f64,
    /// Turn rate, rad/s (body frame z).
    pub(crate) yaw_rate: f64,
}

/// The robot's state `t` seconds after start, starting at phase `theta0` on the path.
pub(crate) fn robot_state(t: f64, theta0: f64) -> RobotState {
    let theta = theta0 + PATH_OMEGA * t;
    let (s1, c1) = theta.sin_cos();
    let (s2, c2) = (2.0 * theta).sin_cos();
    let dx = PATH_A * c1 * PATH_OMEGA;
    let dy = PATH_B * c2 * PATH_OMEGA;
    let ddx = -PATH_A * s1 * PATH_OMEGA * PATH_OMEGA;
    let ddy = -2.0 * PATH_B * s2 * PATH_OMEGA * PATH_OMEGA;
    let speed2 = dx * dx + dy * dy;
    RobotState {
        x: PATH_A * s1,
        y: PATH_B * s1 * c1,
        yaw: dy.atan2(dx),
        speed: speed2.sqrt(),
        yaw_rate: (dx * ddy - dy * ddx) / speed2,
    }
}

/// What a ray hit, for intensities.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Surface {
    Wall,
    Pillar,
    Floor,
    Ceiling,
}

/// Distance along the horizontal ray from `(ox, oy)` in unit direction `(dx, dy)` to the
/// first wall, and to the first pillar (if any is hit before the wall).
/// The origin must be inside the room.
#[inline]
pub(crate) fn cast_2d(ox: f64, oy: f64, dx: f64, dy: f64) -> (f64, Option<f64>) {
    let tx = if dx > 0.0 {
        (HALF_ROOM - ox) / dx
    } else if dx < 0.0 {
        (-HALF_ROOM - ox) / dx
    } else {
        f64::INFINITY
    };
    let ty = if dy > 0.0 {
        (HALF_ROOM - oy) / dy
    } else if dy < 0.0 {
        (-HALF_ROOM - oy) / dy
    } else {
        f64::INFINITY
    };
    let wall = tx.min(ty);
    let mut pillar: Option<f64> = None;
    for &(cx, cy, r) in &PILLARS {
        let fx = ox - cx;
        let fy = oy - cy;
        let b = fx * dx + fy * dy;
        let c = fx * fx + fy * fy - r * r;
        // Origin outside the pillar (c > 0) and pillar ahead (b < 0).
        if c <= 0.0 || b >= 0.0 {
            continue;
        }
        let disc = b * b - c;
        if disc < 0.0 {
            continue;
        }
        let t = -b - disc.sqrt();
        if t < wall && pillar.is_none_or(|p| t < p) {
            pillar = Some(t);
        }
    }
    (wall, pillar)
}

/// Planar range: first hit of walls or pillars.
#[inline]
pub(crate) fn range_2d(ox: f64, oy: f64, dx: f64, dy: f64) -> f64 {
    let (wall, pillar) = cast_2d(ox, oy, dx, dy);
    pillar.unwrap_or(wall)
}

/// 3D ray from `(ox, oy, oz)` with horizontal unit direction `(dx, dy)` and elevation
/// given as `(sin, cos)`: range to the first surface and which one.
#[inline]
pub(crate) fn range_3d(
    ox: f64,
    oy: f64,
    oz: f64,
    dx: f64,
    dy: f64,
    (sin_el, cos_el): (f64, f64),
) -> (f64, Surface) {
    let (wall_h, pillar_h) = cast_2d(ox, oy, dx, dy);
    let mut best = (wall_h / cos_el, Surface::Wall);
    if let Some(h) = pillar_h {
        let z = oz + h * sin_el / cos_el;
        // A ray passing above a pillar could still hit its top disc; ignoring that
        // (it continues to the wall or floor) is close enough for a simulator.
        if (0.0..=PILLAR_HEIGHT).contains(&z) {
            best = (h / cos_el, Surface::Pillar);
        }
    }
    if sin_el < 0.0 {
        let t = -oz / sin_el;
        if t < best.0 {
            best = (t, Surface::Floor);
        }
    } else if sin_el > 0.0 {
        let t = (CEILING - oz) / sin_el;
        if t < best.0 {
            best = (t, Surface::Ceiling);
        }
    }
    best
}

/// Counter-based noise (SplitMix64): cheap, deterministic, seeded per message.
#[derive(Debug, Clone)]
pub(crate) struct Noise(u64);

impl Noise {
    pub(crate) fn new(seed: u64) -> Self {
        Self(seed)
    }

    #[inline]
    pub(crate) fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        mix64(self.0)
    }

    /// Uniform in [0, 1).
    #[inline]
    pub(crate) fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Approximately normal with standard deviation `sigma` (Irwin–Hall of 4 uniforms).
    #[inline]
    pub(crate) fn normal(&mut self, sigma: f64) -> f64 {
        let sum = self.uniform() + self.uniform() + self.uniform() + self.uniform();
        (sum - 2.0) * 3f64.sqrt() * sigma
    }
}

/// SplitMix64 finaliser; also used to derive seeds from (seed, name, topic, slot).
#[inline]
pub(crate) fn mix64(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Stable hash of a robot name (FNV-1a), so robots sharing a seed still differ.
pub(crate) fn name_hash(name: &str) -> u64 {
    name.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// Start phase on the path for a robot, in [0, 2π).
pub(crate) fn start_phase(robot_seed: u64) -> f64 {
    (mix64(robot_seed) >> 11) as f64 / (1u64 << 53) as f64 * TAU
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn path_stays_clear_of_pillars_and_walls() {
        for i in 0..2000 {
            let s = robot_state(f64::from(i) * 0.05, 0.0);
            assert!(
                s.x.abs() < HALF_ROOM - 2.0 && s.y.abs() < HALF_ROOM - 2.0,
                "{s:?}"
            );
            for (cx, cy, r) in PILLARS {
                assert!(
                    ((s.x - cx).powi(2) + (s.y - cy).powi(2)).sqrt() > r + 1.0,
                    "{s:?}"
                );
            }
            assert!((0.45..1.1).contains(&s.speed), "{s:?}");
        }
    }

    #[test]
    fn yaw_rate_matches_heading_change() {
        let dt = 1e-4;
        for i in 0..100 {
            let t = f64::from(i) * 0.7;
            let (a, b) = (robot_state(t, 1.0), robot_state(t + dt, 1.0));
            let dyaw =
                (b.yaw - a.yaw + std::f64::consts::PI).rem_euclid(TAU) - std::f64::consts::PI;
            assert!(
                (dyaw / dt - a.yaw_rate).abs() < 1e-3,
                "t={t}: {} vs {}",
                dyaw / dt,
                a.yaw_rate
            );
        }
    }

    #[test]
    fn rays_hit_walls_and_pillars() {
        assert!((range_2d(0.0, 0.0, 1.0, 0.0) - 3.7).abs() < 1e-9); // pillar at x=4.2, r=0.5
        assert!((range_2d(0.0, 0.0, 0.0, -1.0) - 10.0).abs() < 1e-9);
        let (r, s) = range_3d(0.0, 0.0, 0.4, 0.0, -1.0, (-(0.5f64).sin(), 0.5f64.cos()));
        assert_eq!(s, Surface::Floor);
        assert!((r - 0.4 / 0.5f64.sin()).abs() < 1e-9);
    }
}
