//! The animation as other viewers will play it: one channel per animated
//! field, each a list of linear keys sampled from the authored tracks.
//!
//! Boolean tracks have no interpolator of their own in VRML97 (a Switch
//! needs an SFInt32 event, which only a Script can make), so they are folded
//! into a numeric field that stock viewers do animate:
//! * node visibility multiplies the node's scale (hidden = scale 0 0 0);
//!   a node hidden without a track (or with render style `hidden`) gets a
//!   constant scale-0 channel,
//! * light `on` multiplies the light's intensity (off = intensity 0), and the
//!   file says `on TRUE`.
//!
//! Both folds jump: the sampler writes two keys at the same time there.

use super::sampling::{self, Curve, Sample, Tolerances};
use crate::anim::{Keys, Property, Repeat, TargetRef, Track, Value};
use crate::scene::{NodeKind, RenderStyle, Scene};
use glam::Vec3;

/// One field driven by a linear interpolator.
#[derive(Clone, Debug, PartialEq)]
pub struct Channel {
    pub of: TargetRef,
    /// The field it drives (`Scale` also carries visibility,
    /// `LightIntensity` also carries `on`).
    pub property: Property,
    pub samples: Vec<Sample>,
    /// Authored keys behind this channel.
    pub authored_keys: usize,
    /// When every track behind the channel loops with this period (frames)
    /// and the scene's duration is a whole number (≥ 2) of them: `samples`
    /// hold one period from frame 0, to be played by a clock of their own
    /// (so a loop is not unrolled over the whole duration). The value at
    /// frame `f` is the one at `f mod period`.
    pub period: Option<f32>,
}

impl Channel {
    /// The frame within `samples` that plays at scene frame `f`.
    pub fn local_frame(&self, f: f32) -> f32 {
        match self.period {
            Some(p) => f.rem_euclid(p),
            None => f,
        }
    }
}

/// The common loop period of `tracks` when a clock of its own can play it:
/// all loop with one period `p > 0`, and `duration` is a whole number of at
/// least two periods (then the scene's restart at `duration` is also a
/// restart of the loop, so both clocks stay in step).
fn loop_period(tracks: &[Option<&Track>], duration: f32) -> Option<f32> {
    let mut period = None;
    for t in tracks.iter().flatten() {
        let frames = t.keys.frames();
        let p = frames.last()? - frames.first()?;
        if t.repeat != Repeat::Loop || p <= 0.0 || period.is_some_and(|q| q != p) {
            return None;
        }
        period = Some(p);
    }
    let p = period?;
    let n = duration / p;
    (n >= 2.0 && (n - n.round()).abs() <= 1e-4).then_some(p)
}

/// A channel's value at a frame.
type Eval<'a> = Box<dyn Fn(f32) -> Value + 'a>;

/// Frames where `track` may bend or jump within `0..=duration`.
pub fn track_breaks(track: &Track, duration: f32) -> Vec<f32> {
    let frames = track.keys.frames();
    let (Some(&first), Some(&last)) = (frames.first(), frames.last()) else {
        return Vec::new();
    };
    let period = last - first;
    let mut out = Vec::new();
    if track.repeat == Repeat::Loop && period > 0.0 {
        // Repeats of the key times that fall inside 0..=duration.
        let k0 = ((0.0 - last) / period).floor() as i64;
        let k1 = ((duration - first) / period).ceil() as i64;
        'outer: for k in k0..=k1 {
            for f in &frames {
                let t = f + k as f32 * period;
                if (0.0..=duration).contains(&t) {
                    out.push(t);
                    if out.len() >= sampling::MAX_BREAKS {
                        break 'outer;
                    }
                }
            }
        }
    } else {
        out = frames;
    }
    out
}

fn scale_of(v: Value) -> Vec3 {
    match v {
        Value::Vec3(v) => v,
        Value::Scalar(s) => Vec3::splat(s),
        _ => Vec3::ONE,
    }
}

fn on_of(v: Value) -> bool {
    matches!(v, Value::Bool(true))
}

fn scalar_of(v: Value) -> f32 {
    match v {
        Value::Scalar(s) => s,
        _ => 0.0,
    }
}

/// The channels of `scene`'s animation, sampled within `tol`.
pub fn channels(scene: &Scene, tol: &Tolerances) -> Vec<Channel> {
    let duration = scene.settings.duration;
    // The last track for each target/property wins, as in `anim::evaluate`.
    let find = |of: TargetRef, p: Property| {
        scene
            .animation
            .tracks
            .iter()
            .rev()
            .find(|t| t.target.of == of && t.target.property == p)
    };
    let mut order: Vec<(TargetRef, Property)> = Vec::new();
    for t in &scene.animation.tracks {
        let p = match t.target.property {
            Property::Visibility => Property::Scale,
            Property::LightOn => Property::LightIntensity,
            p => p,
        };
        if !order.contains(&(t.target.of, p)) {
            order.push((t.target.of, p));
        }
    }
    for id in scene.walk() {
        let n = scene.node(id);
        let of = TargetRef::Node(id);
        if (!n.visible || n.style == RenderStyle::Hidden) && !order.contains(&(of, Property::Scale))
        {
            order.push((of, Property::Scale));
        }
    }
    let mut out = Vec::new();
    for (of, property) in order {
        let node = match of {
            TargetRef::Node(id) => match scene.nodes.get(id.0 as usize) {
                Some(n) => Some(n),
                None => continue,
            },
            TargetRef::Material(m) => {
                if scene.materials.get(m.0 as usize).is_none() {
                    continue;
                }
                None
            }
        };
        let main = find(of, property);
        let (eval, used, authored): (Eval, [Option<&Track>; 2], usize) = match property {
            Property::Scale => {
                let Some(node) = node else { continue };
                let vis = find(of, Property::Visibility);
                let hidden = !node.visible || node.style == RenderStyle::Hidden;
                let rest = node.transform.scale;
                let authored = [main, vis]
                    .into_iter()
                    .flatten()
                    .map(|t| t.keys.len())
                    .sum();
                let style_hidden = node.style == RenderStyle::Hidden;
                (
                    Box::new(move |f| {
                        let s = main.map_or(rest, |t| scale_of(t.sample(f)));
                        let shown = match vis {
                            Some(t) => on_of(t.sample(f)) && !style_hidden,
                            None => !hidden,
                        };
                        Value::Vec3(if shown { s } else { Vec3::ZERO })
                    }),
                    [main, vis],
                    authored,
                )
            }
            Property::LightIntensity => {
                let Some(NodeKind::Light(light)) = node.map(|n| &n.kind) else {
                    continue;
                };
                let on = find(of, Property::LightOn);
                let rest = light.intensity;
                // Without an `on` track the light stays as it is at rest:
                // off means intensity 0 all along (animed plays it so).
                let on_at_rest = light.on;
                let authored = [main, on].into_iter().flatten().map(|t| t.keys.len()).sum();
                (
                    Box::new(move |f| {
                        let i = main.map_or(rest, |t| scalar_of(t.sample(f)));
                        let lit = on.map_or(on_at_rest, |t| on_of(t.sample(f)));
                        Value::Scalar(if lit { i } else { 0.0 })
                    }),
                    [main, on],
                    authored,
                )
            }
            _ => {
                let Some(t) = main else { continue };
                if matches!(t.keys, Keys::Bool(_)) {
                    continue;
                }
                (
                    Box::new(move |f| t.sample(f)),
                    [Some(t), None],
                    t.keys.len(),
                )
            }
        };
        // One period when a clock of its own can loop it, else the whole
        // duration.
        let period = loop_period(&used, duration);
        let span = period.unwrap_or(duration);
        let curve = Curve {
            eval: &*eval,
            breaks: used
                .into_iter()
                .flatten()
                .flat_map(|t| track_breaks(t, span))
                .collect(),
            metric: tol.metric(property),
        };
        out.push(Channel {
            of,
            property,
            samples: sampling::sample(&curve, span),
            authored_keys: authored,
            period,
        });
    }
    out
}

/// The scene's size at rest: diagonal of the world-space bounding box of
/// all shapes (1 when there are none).
pub fn scene_diagonal(scene: &Scene) -> f32 {
    let n = scene.nodes.len();
    let mut world = vec![glam::Mat4::IDENTITY; n];
    let mut lo = Vec3::splat(f32::INFINITY);
    let mut hi = Vec3::splat(f32::NEG_INFINITY);
    for id in scene.walk() {
        let i = id.0 as usize;
        let node = scene.node(id);
        let parent = node
            .parent
            .map_or(glam::Mat4::IDENTITY, |p| world[p.0 as usize]);
        world[i] = parent * node.transform.matrix();
        if let NodeKind::Shape(s) = &node.kind {
            if let Some((a, b)) = scene.meshes.get(s.mesh.0 as usize).and_then(|m| m.bounds()) {
                for c in 0..8 {
                    let p = Vec3::new(
                        if c & 1 == 0 { a.x } else { b.x },
                        if c & 2 == 0 { a.y } else { b.y },
                        if c & 4 == 0 { a.z } else { b.z },
                    );
                    let w = world[i].transform_point3(p);
                    lo = lo.min(w);
                    hi = hi.max(w);
                }
            }
        }
    }
    let d = (hi - lo).length();
    if d.is_finite() && d > 0.0 {
        d
    } else {
        1.0
    }
}
