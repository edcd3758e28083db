//! The key strip under the timeline ruler: a summary row with every key of
//! the selected node, one row per animated property below it (collapsible),
//! key selection (click, Shift+click, box), and the edits made there: move
//! (drag, whole-frame steps), scale timing (Alt+drag, about the current
//! frame), delete, copy and paste. A drag previews live and records one
//! [`Command::SetAnimation`] at release; a refused step (two selected keys
//! squeezed onto one frame) keeps the drag's last valid state. The edits
//! themselves are in `keyedit.rs`, the component's event handling in
//! `keystrip_ui.rs`, drawing in `keystrip_draw.rs`, the key properties
//! panel in `keyprops.rs`.

use crate::anim::{Animation, Key, Property, Target, TargetRef, Value, KEY_EPS};
use crate::scene::NodeId;

/// One key: a node property's track and the key's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KeyRef {
    pub node: NodeId,
    pub property: Property,
    pub frame: f32,
}

impl KeyRef {
    pub fn target(&self) -> Target {
        Target {
            of: TargetRef::Node(self.node),
            property: self.property,
        }
    }

    /// Same track and frame (within [`KEY_EPS`]).
    pub fn same(&self, o: &KeyRef) -> bool {
        self.node == o.node
            && self.property == o.property
            && (self.frame - o.frame).abs() <= KEY_EPS
    }

    /// The key in `anim`, if it exists.
    pub fn get(&self, anim: &Animation) -> Option<Key<Value>> {
        let t = anim.track(self.target())?;
        t.key(t.key_index_at(self.frame)?)
    }
}

/// A row of the strip.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Row {
    /// All keys of the selection; its name cell folds the property rows.
    Summary,
    Track(Property),
    /// Rows that did not fit.
    More(usize),
}

/// What is under the mouse in the strip.
#[derive(Clone, Debug, PartialEq)]
pub enum Hit {
    /// The name cell of a row.
    Name(Row),
    /// A marker: the keys it stands for (one, or all at a summary frame).
    Keys(Vec<KeyRef>),
    /// Empty row space.
    Empty,
}

/// A mouse drag that started in the strip.
#[derive(Clone, Debug)]
pub enum StripDrag {
    /// Pressed on a marker: moves (or with Alt scales) `keys` from `base`.
    Keys {
        x0: f32,
        base: Box<Animation>,
        keys: Vec<KeyRef>,
        scale: bool,
        moved: bool,
        /// A click (no drag) on an already selected key selects just it.
        narrow_to: Option<Vec<KeyRef>>,
    },
    /// Pressed on empty space: a selection box.
    Box {
        from: (f32, f32),
        to: (f32, f32),
        add: bool,
        before: Vec<KeyRef>,
    },
}

/// Keys copied with Ctrl+C: frames relative to the earliest.
#[derive(Clone, Debug, Default)]
pub(super) struct Clipboard {
    pub(super) keys: Vec<(crate::anim::Property, crate::anim::Key<crate::anim::Value>)>,
}

/// Key strip state kept by the editor.
#[derive(Clone, Debug, Default)]
pub struct KeyStrip {
    pub(super) selected: Vec<KeyRef>,
    pub collapsed: bool,
    pub(super) clipboard: Clipboard,
    /// Recent (animation, key selection) pairs, newest last: undo and redo
    /// bring back the selection that went with the animation they restore.
    pub(super) memo: Vec<(Animation, Vec<KeyRef>)>,
    /// First row shown (rows scroll inside the strip's fixed height).
    pub scroll: usize,
    /// The drag the strip runs, if any (the editor's gesture is then
    /// `Drag::Keys`).
    pub(super) drag: Option<StripDrag>,
}

/// Pairs kept in [`KeyStrip::memo`].
pub(super) const MEMO: usize = 8;

/// Half size of a marker in pixels (also the click tolerance).
pub const MARKER_R: f32 = 4.5;

/// The row name shown at the left of the strip.
pub fn row_name(p: Property) -> &'static str {
    match p {
        Property::Translation => "Translation",
        Property::Rotation => "Rotation",
        Property::Scale => "Scale",
        Property::Visibility => "Visible",
        Property::LightOn => "Light on",
        Property::LightIntensity => "Intensity",
        Property::LightColor => "Colour",
        Property::LightLocation => "Location",
        Property::LightDirection => "Direction",
        Property::LightCutOff => "Cut-off",
        Property::LightBeamWidth => "Beam width",
        Property::LightDropOff => "Drop-off",
        Property::CameraPosition => "Position",
        Property::CameraOrientation => "Orientation",
        Property::CameraFov => "Field of vw",
        Property::Diffuse => "Diffuse",
        Property::Emissive => "Emissive",
        Property::Specular => "Specular",
        Property::Transparency => "Transparent",
        Property::MorphWeights => "Morph wts",
        Property::Shininess => "Shininess",
    }
}

/// Properties of node `id` driven by tracks, in [`Property::ALL`] order.
pub fn animated_properties(anim: &Animation, id: NodeId) -> Vec<Property> {
    let mut v: Vec<Property> = anim
        .tracks_of(TargetRef::Node(id))
        .map(|t| t.target.property)
        .collect();
    v.sort_by_key(|p| Property::ALL.iter().position(|q| q == p));
    v.dedup();
    v
}

/// Every key of `id`'s track for `p`.
pub fn track_keys(anim: &Animation, id: NodeId, p: Property) -> Vec<KeyRef> {
    let t = Target {
        of: TargetRef::Node(id),
        property: p,
    };
    anim.track(t)
        .map(|t| {
            t.keys
                .frames()
                .into_iter()
                .map(|frame| KeyRef {
                    node: id,
                    property: p,
                    frame,
                })
                .collect()
        })
        .unwrap_or_default()
}

/// Every key of node `id`.
pub fn node_keys(anim: &Animation, id: NodeId) -> Vec<KeyRef> {
    animated_properties(anim, id)
        .into_iter()
        .flat_map(|p| track_keys(anim, id, p))
        .collect()
}

/// Appends the keys of `ks` not already in `v`.
pub(super) fn add_unique(v: &mut Vec<KeyRef>, ks: impl IntoIterator<Item = KeyRef>) {
    for k in ks {
        if !v.iter().any(|o| o.same(&k)) {
            v.push(k);
        }
    }
}
