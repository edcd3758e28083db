//! TimeSensor → interpolator → ROUTE chains as animation tracks.
//!
//! An interpolator's key `k` (a fraction of the cycle) becomes a key at
//! `(startTime + k · cycleInterval) · fps` frames with linear interpolation
//! (slerp for rotations). Keys are padded to the whole cycle so that a
//! looping track repeats exactly one cycle. ColorInterpolator blends in HSV
//! (VRML97 §6.10), so each colour segment is subdivided with HSV-blended keys.

use super::build::Builder;
use super::geometry;
use super::touch_clips;
use crate::anim::{
    Interp, Key, Keys, Property, Repeat, Target, TargetRef, Track, Weights, MAX_MORPH_TARGETS,
};
use crate::format::hsv::{hsv_to_rgb, lerp_hsv, rgb_to_hsv};
use crate::format::syntax::{AstNode, NodeRef, Route};
use crate::format::x3d::interp as x3d_interp;
use crate::scene::{NodeId, NodeKind, Settings};
use glam::{Quat, Vec3};
use std::collections::{HashMap, HashSet};
use std::rc::Rc;

/// Frame rates tried, in order, for one that puts every key on a whole frame.
const FPS_CHOICES: &[f32] = &[24.0, 25.0, 30.0, 60.0, 50.0, 48.0, 100.0, 120.0];
/// Keys added inside each HSV colour segment.
const HSV_STEPS: usize = 8;

/// A TimeSensor's timing.
#[derive(Clone, Copy, Debug)]
struct Clock {
    start: f64,
    cycle: f64,
    looping: bool,
}

fn clock(ts: &AstNode) -> Clock {
    Clock {
        start: ts.num("startTime").unwrap_or(0.0).max(0.0),
        cycle: ts.num("cycleInterval").unwrap_or(1.0),
        looping: ts.bool("loop", false),
    }
}

/// Strips `set_` and `_changed` from an event name.
fn field_name(s: &str) -> &str {
    let s = s.strip_prefix("set_").unwrap_or(s);
    s.strip_suffix("_changed").unwrap_or(s)
}

/// Follows PROTO interface bindings to the real (node, field) pairs.
pub(super) fn resolve(node: &NodeRef, field: &str, out: &mut Vec<(NodeRef, String)>, depth: usize) {
    if depth > 64 {
        return;
    }
    match &node.proto {
        Some(p) => {
            let bound = p
                .is_map
                .get(field)
                .or_else(|| p.is_map.get(field_name(field)))
                .or_else(|| p.is_map.get(&format!("set_{}", field_name(field))))
                .or_else(|| p.is_map.get(&format!("{}_changed", field_name(field))));
            if let Some(list) = bound {
                for (n, f) in list {
                    resolve(n, f, out, depth + 1);
                }
            }
        }
        None => out.push((node.clone(), field.to_string())),
    }
}

/// One interpolator's keys as seconds-in-cycle fractions and values.
enum Values {
    Scalar(Vec<f32>),
    Vec3(Vec<Vec3>),
    Rotation(Vec<Quat>),
    Color(Vec<Vec3>),
}

fn interpolator_values(n: &AstNode) -> Option<(Vec<f64>, Values)> {
    let keys: Vec<f64> = n.nums("key")?.to_vec();
    let kv = n.nums("keyValue").unwrap_or(&[]);
    let v3 = |kv: &[f64]| -> Vec<Vec3> {
        kv.chunks_exact(3)
            .map(|c| Vec3::new(c[0] as f32, c[1] as f32, c[2] as f32))
            .collect()
    };
    let values = match n.kind.as_str() {
        "ScalarInterpolator" => Values::Scalar(kv.iter().map(|v| *v as f32).collect()),
        "PositionInterpolator" => Values::Vec3(v3(kv)),
        "ColorInterpolator" => Values::Color(v3(kv)),
        "OrientationInterpolator" => Values::Rotation(
            kv.chunks_exact(4)
                .map(|c| crate::format::syntax::axis_angle(c[0], c[1], c[2], c[3]))
                .collect(),
        ),
        _ => return None,
    };
    Some((keys, values))
}

/// Which property a routed field is, given what the target node is.
enum Dest {
    Node(Property),
    Material(Property),
}

fn dest(target_kind: &str, field: &str) -> Option<Dest> {
    use Property as P;
    let f = field_name(field);
    let p = match (target_kind, f) {
        ("Transform", "translation") => Dest::Node(P::Translation),
        ("Transform", "rotation") => Dest::Node(P::Rotation),
        ("Transform", "scale") => Dest::Node(P::Scale),
        ("DirectionalLight" | "PointLight" | "SpotLight", f) => Dest::Node(match f {
            "color" => P::LightColor,
            "intensity" => P::LightIntensity,
            "location" => P::LightLocation,
            "direction" => P::LightDirection,
            "cutOffAngle" => P::LightCutOff,
            "beamWidth" => P::LightBeamWidth,
            _ => return None,
        }),
        ("Viewpoint", "position") => Dest::Node(P::CameraPosition),
        ("Viewpoint", "orientation") => Dest::Node(P::CameraOrientation),
        ("Viewpoint", "fieldOfView") => Dest::Node(P::CameraFov),
        ("Material", f) => Dest::Material(match f {
            "diffuseColor" => P::Diffuse,
            "emissiveColor" => P::Emissive,
            "specularColor" => P::Specular,
            "transparency" => P::Transparency,
            "shininess" => P::Shininess,
            _ => return None,
        }),
        _ => return None,
    };
    Some(p)
}

/// Imports every interpolator chain of the file as tracks.
pub fn import(b: &mut Builder, routes: &[Route]) {
    // Interpolator → the TimeSensor that drives its fraction (and the X3D
    // EaseInEaseOut that remaps it on the way, if any).
    let mut driver: HashMap<*const AstNode, NodeRef> = HashMap::new();
    let mut eased: HashMap<*const AstNode, NodeRef> = HashMap::new();
    for r in routes {
        let from = r.from.effective();
        if from.kind == "TimeSensor" && field_name(&r.from_field) == "fraction" {
            let mut targets = Vec::new();
            resolve(&r.to, &r.to_field, &mut targets, 0);
            for (t, f) in targets {
                if field_name(&f) == "fraction" {
                    driver.insert(Rc::as_ptr(&t), from.clone());
                }
            }
        }
    }
    for r in routes {
        let from = r.from.effective();
        let Some(ts) = driver.get(&Rc::as_ptr(&from)).cloned() else {
            continue;
        };
        if from.kind == "EaseInEaseOut" && field_name(&r.from_field) == "modifiedFraction" {
            let mut targets = Vec::new();
            resolve(&r.to, &r.to_field, &mut targets, 0);
            for (t, f) in targets {
                if field_name(&f) == "fraction" {
                    driver.insert(Rc::as_ptr(&t), ts.clone());
                    eased.insert(Rc::as_ptr(&t), from.clone());
                }
            }
        }
    }
    struct Pending {
        interp: NodeRef,
        ease: Option<NodeRef>,
        sensor: NodeRef,
        clock: Clock,
        of: TargetRef,
        property: Property,
    }
    let mut pending: Vec<Pending> = Vec::new();
    // CoordinateInterpolators: (interpolator, clock, Coordinate node, sensor).
    let mut coord_pending: Vec<(NodeRef, Clock, *const AstNode, NodeRef)> = Vec::new();
    // NormalInterpolators: (interpolator, Normal node); each rides on the
    // CoordinateInterpolator of the same shape when their keys agree.
    let mut normal_pending: Vec<(NodeRef, *const AstNode)> = Vec::new();
    for r in routes {
        let mut sources = Vec::new();
        resolve(&r.from, &r.from_field, &mut sources, 0);
        let Some((interp, _)) = sources.into_iter().next() else {
            continue;
        };
        if !interp.kind.ends_with("Interpolator") || field_name(&r.from_field) != "value" {
            continue;
        }
        let Some(ts) = driver.get(&Rc::as_ptr(&interp)).cloned() else {
            let msg = format!(
                "{} is not driven by a TimeSensor's fraction_changed; not imported",
                interp.kind
            );
            b.warn(r.pos, &msg);
            continue;
        };
        let c = clock(&ts);
        if !ts.bool("enabled", true) {
            b.warn(
                ts.pos,
                "TimeSensor is disabled (enabled FALSE); its animation is not imported",
            );
            continue;
        }
        if !(c.cycle > 0.0 && c.cycle.is_finite()) {
            b.warn(
                ts.pos,
                "TimeSensor cycleInterval must be > 0; its animation is not imported",
            );
            continue;
        }
        if interp.kind == "NormalInterpolator" {
            let mut targets = Vec::new();
            resolve(&r.to, &r.to_field, &mut targets, 0);
            for (t, f) in targets {
                let t = t.effective();
                if t.kind == "Normal" && field_name(&f) == "vector" {
                    normal_pending.push((interp.clone(), Rc::as_ptr(&t)));
                }
            }
            continue;
        }
        if interp.kind == "CoordinateInterpolator" {
            let mut targets = Vec::new();
            resolve(&r.to, &r.to_field, &mut targets, 0);
            for (t, f) in targets {
                let t = t.effective();
                if t.kind == "Coordinate" && field_name(&f) == "point" {
                    coord_pending.push((interp.clone(), c, Rc::as_ptr(&t), ts.clone()));
                } else {
                    let msg = format!(
                        "animating {}.{} is not supported; not imported",
                        t.kind,
                        field_name(&f)
                    );
                    b.warn_once(&msg.clone(), r.pos, &msg);
                }
            }
            continue;
        }
        let mut targets = Vec::new();
        resolve(&r.to, &r.to_field, &mut targets, 0);
        for (t, f) in targets {
            let t = t.effective();
            match dest(&t.kind, &f) {
                Some(Dest::Node(property)) => {
                    let ids = b
                        .instances
                        .get(&Rc::as_ptr(&t))
                        .cloned()
                        .unwrap_or_default();
                    for id in ids {
                        // A light/camera property only applies to that kind of node.
                        let ok = matches!(
                            (&b.scene.node(id).kind, property.owner()),
                            (NodeKind::Light(_), "light")
                                | (NodeKind::Camera(_), "camera")
                                | (_, "node")
                        );
                        if ok {
                            pending.push(Pending {
                                interp: interp.clone(),
                                ease: eased.get(&Rc::as_ptr(&interp)).cloned(),
                                sensor: ts.clone(),
                                clock: c,
                                of: TargetRef::Node(id),
                                property,
                            });
                        }
                    }
                }
                Some(Dest::Material(property)) => {
                    let base = b.materials.get(&Rc::as_ptr(&t)).copied();
                    let copies = b.material_copies.get(&Rc::as_ptr(&t));
                    let ids = base
                        .into_iter()
                        .chain(copies.into_iter().flatten().copied());
                    for id in ids.collect::<Vec<_>>() {
                        pending.push(Pending {
                            interp: interp.clone(),
                            ease: eased.get(&Rc::as_ptr(&interp)).cloned(),
                            sensor: ts.clone(),
                            clock: c,
                            of: TargetRef::Material(id),
                            property,
                        });
                    }
                }
                None => {
                    let msg = format!(
                        "animating {}.{} is not supported; not imported",
                        t.kind,
                        field_name(&f)
                    );
                    b.warn_once(&msg.clone(), r.pos, &msg);
                }
            }
        }
    }
    if pending.is_empty() && coord_pending.is_empty() {
        return;
    }
    // One frame rate for the whole file.
    let mut seconds = Vec::new();
    let clocks = pending
        .iter()
        .map(|p| (&p.interp, p.clock))
        .chain(coord_pending.iter().map(|(i, c, _, _)| (i, *c)));
    for (interp, clock) in clocks.clone() {
        if let Some(keys) = interp.nums("key") {
            seconds.extend(keys.iter().map(|k| clock.start + k * clock.cycle));
        }
        seconds.push(clock.start + clock.cycle);
    }
    // Tracks grafted from Inline files already use the current frame rate.
    let fps = if b.scene.animation.tracks.is_empty() {
        pick_fps(&seconds)
    } else {
        b.scene.settings.fps
    };
    let mut settings = Settings {
        fps,
        ..b.scene.settings.clone()
    };
    let end = clocks
        .map(|(_, c)| (c.start + c.cycle) * fps as f64)
        .fold(0.0f64, f64::max);
    settings.duration = if b.scene.animation.tracks.is_empty() {
        end as f32
    } else {
        settings.duration.max(end as f32)
    };
    b.scene.settings = settings;

    // Which sensor each new track follows (for the clips of sensors that
    // wait for an event, `touch_clips`).
    let first = b.scene.animation.tracks.len();
    let mut owners: Vec<(usize, NodeRef)> = Vec::new();
    for p in pending {
        let made = if x3d_interp::handles(&p.interp, p.ease.as_deref()) {
            // X3D splines, squad and EaseInEaseOut: exact keys or samples.
            let c = p.clock;
            let frame = |k: f64| ((c.start + k * c.cycle) * fps as f64) as f32;
            match x3d_interp::keys(&p.interp, p.ease.as_deref(), p.property.kind(), &frame) {
                Some((keys, _exact)) => Ok(keys),
                None => Err(format!(
                    "{} keys do not fit {}; not imported",
                    p.interp.kind,
                    p.property.name()
                )),
            }
        } else {
            let Some((fractions, values)) = interpolator_values(&p.interp) else {
                continue;
            };
            let n = match &values {
                Values::Scalar(v) => v.len(),
                Values::Vec3(v) | Values::Color(v) => v.len(),
                Values::Rotation(v) => v.len(),
            };
            if n != fractions.len() && n > 0 && !fractions.is_empty() {
                let msg = format!(
                    "{}: {} key times but {n} keyValues (VRML97 wants one value per key); \
                     the first {} of each are used",
                    p.interp.kind,
                    fractions.len(),
                    n.min(fractions.len())
                );
                b.warn(p.interp.pos, &msg);
            }
            make_keys(&fractions, values, p.clock, fps, p.property)
        };
        match made {
            Ok(keys) => {
                let target = Target {
                    of: p.of,
                    property: p.property,
                };
                let repeat = if p.clock.looping {
                    Repeat::Loop
                } else {
                    Repeat::Constant
                };
                match Track::new(target, repeat, keys) {
                    Ok(t) => {
                        owners.push((b.scene.animation.tracks.len(), p.sensor.clone()));
                        b.scene.animation.tracks.push(t);
                    }
                    Err(e) => {
                        let msg = format!("{} not imported: {e}", p.interp.kind);
                        b.warn(p.interp.pos, &msg);
                    }
                }
            }
            Err(msg) => b.warn(p.interp.pos, &msg),
        }
    }
    let mut normals_used: HashSet<*const AstNode> = HashSet::new();
    for (interp, c, coord, sensor) in coord_pending {
        let before = b.scene.animation.tracks.len();
        import_coordinates(
            b,
            &interp,
            c,
            coord,
            fps,
            &normal_pending,
            &mut normals_used,
        );
        let after = b.scene.animation.tracks.len();
        owners.extend((before..after).map(|i| (i, sensor.clone())));
    }
    for (interp, _) in &normal_pending {
        if !normals_used.contains(&Rc::as_ptr(interp)) {
            b.warn_once(
                "NormalInterpolator",
                interp.pos,
                "NormalInterpolator not imported: only one that moves with a \
                 CoordinateInterpolator of the same shape (same keys) is read; normals are \
                 recomputed at each key instead",
            );
        }
    }
    let waiting = touch_clips::event_started(routes);
    touch_clips::split(b, first, &owners, &waiting, |ts| {
        let c = clock(ts);
        ((c.start + c.cycle) * fps as f64) as f32
    });
}

/// The key normals of the NormalInterpolator driving `g`'s Normal with
/// the same key fractions as `coords`, one vector list per key.
fn normal_keys(
    g: &AstNode,
    coords: &AstNode,
    pending: &[(NodeRef, *const AstNode)],
) -> Option<(NodeRef, Vec<Vec<Vec3>>)> {
    let normal = g.node("normal")?.effective();
    let (interp, _) = pending.iter().find(|(_, n)| *n == Rc::as_ptr(&normal))?;
    let fractions = interp.nums("key").unwrap_or(&[]);
    if fractions != coords.nums("key").unwrap_or(&[]) || fractions.is_empty() {
        return None;
    }
    let kv = interp.nums("keyValue").unwrap_or(&[]);
    let per = normal.nums("vector").map_or(0, |v| v.len());
    if per == 0 || kv.len() != per * fractions.len() {
        return None;
    }
    Some((interp.clone(), point_sets(kv, per)))
}

/// An interpolator's keyValue as one point (or vector) set per key, `per`
/// numbers each.
fn point_sets(kv: &[f64], per: usize) -> Vec<Vec<Vec3>> {
    kv.chunks_exact(per)
        .map(|k| {
            k.chunks_exact(3)
                .map(|p| Vec3::new(p[0] as f32, p[1] as f32, p[2] as f32))
                .collect()
        })
        .collect()
}

/// A CoordinateInterpolator as morph targets plus a weights track.
///
/// Why targets (and not a per-key vertex track): key i's point set becomes
/// target i (its offsets from the Coordinate's points) and the weights are
/// one-hot at each key with linear keys in between, so between keys i and
/// i+1 the mesh is B + (1−s)(Kᵢ−B) + s(Kᵢ₊₁−B) = (1−s)Kᵢ + sKᵢ₊₁: exactly
/// the spec's linear interpolation of keyValue. It needs nothing beyond the
/// morph model glTF also uses (keys, the key note, the editor and every
/// writer treat it as any weights track), and evaluation touches only the
/// two targets with non-zero weights. The cost: at most
/// [`MAX_MORPH_TARGETS`] keys per interpolator.
fn import_coordinates(
    b: &mut Builder,
    interp: &NodeRef,
    c: Clock,
    coord: *const AstNode,
    fps: f32,
    normal_pending: &[(NodeRef, *const AstNode)],
    normals_used: &mut HashSet<*const AstNode>,
) {
    let fractions: Vec<f64> = interp.nums("key").unwrap_or(&[]).to_vec();
    let kv = interp.nums("keyValue").unwrap_or(&[]);
    let n = fractions.len();
    let users = b.coord_users.get(&coord).cloned().unwrap_or_default();
    if users.is_empty() {
        b.warn(
            interp.pos,
            "CoordinateInterpolator drives a Coordinate no IndexedFaceSet uses; not imported",
        );
        return;
    }
    if n == 0 || !kv.len().is_multiple_of(3 * n) {
        b.warn(
            interp.pos,
            "CoordinateInterpolator keyValue is not one point set per key; not imported",
        );
        return;
    }
    if n > MAX_MORPH_TARGETS {
        let msg = format!(
            "CoordinateInterpolator has {n} keys; animed holds at most {MAX_MORPH_TARGETS} per mesh; not imported"
        );
        b.warn(interp.pos, &msg);
        return;
    }
    if fractions
        .windows(2)
        .any(|w| w[1] < w[0] || !w[0].is_finite() || !w[1].is_finite())
    {
        b.warn(
            interp.pos,
            "interpolator keys are not in ascending order; not imported",
        );
        return;
    }
    let per = kv.len() / n;
    let keys = point_sets(kv, per);
    let onehot: Vec<Weights> = (0..n)
        .map(|i| {
            let mut w = Weights::zeros(n);
            w.as_mut_slice()[i] = 1.0;
            w
        })
        .collect();
    let frame = |k: f64| ((c.start + k * c.cycle) * fps as f64) as f32;
    let repeat = if c.looping {
        Repeat::Loop
    } else {
        Repeat::Constant
    };
    for (geom, textured, mesh) in users {
        let with_normals = normal_keys(&geom, interp, normal_pending);
        if let Some((n, _)) = &with_normals {
            normals_used.insert(Rc::as_ptr(n));
        }
        let nk = with_normals.as_ref().map(|(_, k)| k.as_slice());
        match geometry::ifs_morph(&geom, textured, &keys, nk) {
            Ok(m) => b.scene.meshes[mesh.0 as usize].morph = Some(Box::new(m)),
            Err(e) => {
                let msg = format!("CoordinateInterpolator not imported: {e}");
                b.warn(interp.pos, &msg);
                continue;
            }
        }
        let shapes: Vec<NodeId> = (0..b.scene.nodes.len())
            .map(|i| NodeId(i as u32))
            .filter(|&id| matches!(&b.scene.node(id).kind, NodeKind::Shape(s) if s.mesh == mesh))
            .collect();
        for id in shapes {
            let target = Target {
                of: TargetRef::Node(id),
                property: Property::MorphWeights,
            };
            match Track::new(
                target,
                repeat,
                Keys::Weights(keyed(&fractions, &onehot, frame)),
            ) {
                Ok(t) => b.scene.animation.tracks.push(t),
                Err(e) => {
                    let msg = format!("CoordinateInterpolator not imported: {e}");
                    b.warn(interp.pos, &msg);
                }
            }
        }
    }
}

fn pick_fps(seconds: &[f64]) -> f32 {
    for &fps in FPS_CHOICES {
        let exact = seconds.iter().all(|s| {
            let f = s * fps as f64;
            (f - f.round()).abs() < 1e-4
        });
        if exact {
            return fps;
        }
    }
    24.0
}

/// Builds the keys of one track.
fn make_keys(
    fractions: &[f64],
    values: Values,
    c: Clock,
    fps: f32,
    property: Property,
) -> Result<Keys, String> {
    use crate::anim::ValueKind;
    let n = match &values {
        Values::Scalar(v) => v.len(),
        Values::Vec3(v) | Values::Color(v) => v.len(),
        Values::Rotation(v) => v.len(),
    };
    let count = fractions.len().min(n);
    if count == 0 {
        return Err("interpolator has no keys (key or keyValue empty); not imported".into());
    }
    if fractions.len() != n {
        // Spec: key and keyValue must match; use the common prefix.
    }
    for w in fractions[..count].windows(2) {
        if w[1] < w[0] || !w[0].is_finite() || !w[1].is_finite() {
            return Err("interpolator keys are not in ascending order; not imported".into());
        }
    }
    let frame = |k: f64| ((c.start + k * c.cycle) * fps as f64) as f32;
    let want = property.kind();
    let keys = match values {
        Values::Scalar(v) if want == ValueKind::Scalar => {
            Keys::Scalar(keyed(&fractions[..count], &v[..count], frame))
        }
        Values::Vec3(v) if matches!(want, ValueKind::Vec3 | ValueKind::Color) => {
            Keys::Vec3(keyed(&fractions[..count], &v[..count], frame))
        }
        Values::Color(v) if matches!(want, ValueKind::Vec3 | ValueKind::Color) => {
            let (f, v) = hsv_resample(&fractions[..count], &v[..count]);
            Keys::Vec3(keyed(&f, &v, frame))
        }
        Values::Rotation(mut v) if want == ValueKind::Rotation => {
            // Shortest path between keys (VRML97 §6.32), whichever way the
            // animation core treats quaternion signs.
            for i in 1..count {
                if v[i - 1].dot(v[i]) < 0.0 {
                    v[i] = -v[i];
                }
            }
            Keys::Rotation(keyed(&fractions[..count], &v[..count], frame))
        }
        _ => {
            return Err(format!(
                "interpolator value type does not fit {}; not imported",
                property.name()
            ))
        }
    };
    Ok(keys)
}

/// Linear keys padded to the whole cycle [0, 1]; equal key times (a jump)
/// become two keys a thousandth of a frame apart.
fn keyed<V: Copy>(fractions: &[f64], values: &[V], frame: impl Fn(f64) -> f32) -> Vec<Key<V>> {
    let mut out: Vec<Key<V>> = Vec::with_capacity(values.len() + 2);
    let mut push = |f: f32, v: V| {
        let n = out.len();
        if n > 0 && f <= out[n - 1].frame {
            // A jump: move the earlier key back a hair.
            let prev = if n >= 2 { Some(out[n - 2].frame) } else { None };
            let back = out[n - 1].frame - 1e-3;
            if prev.is_none_or(|p| back > p) {
                out[n - 1].frame = back;
            } else {
                // A third key at the same time: keep the latest value.
                out[n - 1].value = v;
                return;
            }
        }
        out.push(Key::new(f, v).with_interp(Interp::Linear));
    };
    let first = fractions[0];
    if first > 0.0 {
        push(frame(0.0), values[0]);
    }
    for (k, v) in fractions.iter().zip(values) {
        push(frame(k.clamp(0.0, 1.0)), *v);
    }
    if *fractions.last().unwrap_or(&1.0) < 1.0 {
        push(frame(1.0), values[values.len() - 1]);
    }
    out
}

/// Adds HSV-blended keys inside each colour segment so that linear RGB
/// playback follows the HSV path the spec asks for.
fn hsv_resample(fractions: &[f64], colors: &[Vec3]) -> (Vec<f64>, Vec<Vec3>) {
    let mut f = Vec::new();
    let mut c = Vec::new();
    for i in 0..colors.len() {
        f.push(fractions[i]);
        c.push(colors[i]);
        if i + 1 < colors.len() && fractions[i + 1] > fractions[i] {
            let (a, b) = (rgb_to_hsv(colors[i]), rgb_to_hsv(colors[i + 1]));
            let rgb_path_differs = (1..HSV_STEPS).any(|s| {
                let t = s as f32 / HSV_STEPS as f32;
                (hsv_to_rgb(lerp_hsv(a, b, t)) - colors[i].lerp(colors[i + 1], t))
                    .abs()
                    .max_element()
                    > 1e-3
            });
            if rgb_path_differs {
                for s in 1..HSV_STEPS {
                    let t = s as f32 / HSV_STEPS as f32;
                    f.push(fractions[i] + (fractions[i + 1] - fractions[i]) * t as f64);
                    c.push(hsv_to_rgb(lerp_hsv(a, b, t)));
                }
            }
        }
    }
    (f, c)
}
