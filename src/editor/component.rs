//! What the editor's parts (components) hand back to the editor: a
//! [`Response`] says whether the event was theirs and whether the picture
//! changed, and carries [`Intent`]s, the changes they ask for. Components
//! never touch the scene or the history; the editor applies intents, and
//! scene changes go through undoable commands (egui's `Context::run`
//! returning its side effects is the model).

use crate::anim::Animation;
use crate::anim::Property;
use crate::editor::fields::FieldId;
use crate::editor::keystrip::KeyRef;
use crate::editor::material::{MatBase, MatField};
use crate::editor::rig::state::MorphBase;
use crate::input::OrbitCamera;
use crate::scene::{Material, MaterialId, MorphTarget, Node, NodeId, Settings};

/// What the keys components (key strip, graph editor) see of the editor
/// alike: the animation, the selected object and its name, the current
/// frame and the scene's length. Their contexts add their own areas and
/// deref to this.
#[derive(Clone, Debug)]
pub struct Keyed<'a> {
    pub anim: &'a Animation,
    /// The selected object (its keys or channels are shown).
    pub node: Option<NodeId>,
    pub node_name: String,
    /// The selected shape's morph targets (their names label the weight
    /// curves); empty for anything else.
    pub morph_targets: &'a [MorphTarget],
    pub frame: f32,
    pub duration: f32,
}

/// A change a component asks the editor to make.
#[derive(Clone, Debug, PartialEq)]
pub enum Intent {
    /// Show this animation now (a drag in progress); not recorded.
    Preview(Animation),
    /// Record `before` → `after` as one undo step (the scene may already
    /// show `after` through previews).
    Commit {
        label: String,
        before: Animation,
        after: Animation,
    },
    /// Make these the selected keys (the key strip and key panel follow).
    SelectKeys(Vec<KeyRef>),
    /// Show these keys selected while a drag previews them (they moved),
    /// without remembering the selection for undo as `SelectKeys` does.
    ShowKeys(Vec<KeyRef>),
    /// Go to this frame.
    Seek(f32),
    /// A line for the status bar (true: an error).
    Status(String, bool),
    /// A right click at this window point: open the keys' context menu
    /// there (`keymenu.rs`).
    ContextMenu((f32, f32)),
    /// Stop playback (a drag starts).
    StopPlayback,
    /// Show node `id` as `node` while a drag changes `property`: a live
    /// preview, kept over its tracks as a change not yet keyed.
    ShowNode {
        id: NodeId,
        property: Property,
        node: Box<Node>,
    },
    /// Put node `id` back as `node` (the drag's previews go; nothing is
    /// recorded).
    PutBack { id: NodeId, node: Box<Node> },
    /// Record `before` → `after` of node `id` as one undo step (in record
    /// mode with a key on `property`).
    RecordNode {
        label: String,
        id: NodeId,
        before: Box<Node>,
        after: Box<Node>,
        property: Property,
    },
    /// Start typing into `field`, its text `text` (selected, so the
    /// first typed character replaces it).
    Type { field: FieldId, text: String },
    /// Make `node` the selection (a list row was pressed).
    Select(NodeId),
    /// Put `node` under `parent` in the scene tree (`None`: top level).
    Reparent {
        node: NodeId,
        parent: Option<NodeId>,
    },
    /// Look through this camera (the viewport's orbit, pan and zoom).
    Camera(OrbitCamera),
    /// Select what the viewport shows at this window pixel (nothing there
    /// clears the selection): a click in the viewport.
    Pick((f32, f32)),
    /// Open the viewport's context menu at this window pixel.
    ViewportMenu((f32, f32)),
    /// Show the IK chain's two joints posed so (an IK drag; kept pending
    /// over their tracks, `rig/ik.rs`).
    IkPose(Box<[(NodeId, Node); 2]>),
    /// The IK drag ended: record its pose, or keep it pending on animated
    /// joints until K.
    IkDone,
    /// Show material `id` as `value` while a drag changes `props` (kept
    /// pending over their tracks until recorded or dropped).
    ShowMaterial {
        id: MaterialId,
        props: Vec<Property>,
        value: Box<Material>,
    },
    /// Set material field `field` to `value`, from `base`, by the record
    /// rules (`material/route.rs`): a typed value or a drag's release.
    SetMaterial {
        field: MatField,
        base: Box<MatBase>,
        value: f32,
    },
    /// Drop the material change a drag showed (Esc).
    DropMaterial,
    /// Show the morph weights `base` started from with weight `index` at
    /// `value` while a slider is dragged (kept pending like a material).
    ShowWeight {
        base: Box<MorphBase>,
        index: u8,
        value: f32,
    },
    /// Set weight `index` to `value`, from `base`, by the record rules
    /// (`rig/morph.rs`).
    SetWeight {
        base: Box<MorphBase>,
        index: u8,
        value: f32,
    },
    /// Drop the weights a slider drag showed (Esc).
    DropWeights,
    /// Rename the playing clip to what was typed.
    RenameClip(String),
    /// Record node `id` (as stored now) becoming `after` as one undo
    /// step with the record rules for `props` (record mode keys them;
    /// otherwise a change on an animated property is left pending for K):
    /// a node field typed, or its drag released.
    SetNode {
        label: String,
        id: NodeId,
        after: Box<Node>,
        props: Vec<Property>,
    },
    /// Show these scene settings (a drag on fps or len; not recorded).
    PreviewSettings(Settings),
    /// Record the scene settings `before` → `after` as one undo step.
    SetSettings {
        label: String,
        before: Settings,
        after: Settings,
    },
    /// The scene's length was typed: say how many keys lie after its end
    /// (and cut the preview range to it).
    NoteKeysAfterEnd,
}

/// A component's answer to one event.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Response {
    /// The event was the component's (the editor routes it nowhere else).
    pub consumed: bool,
    pub redraw: bool,
    pub intents: Vec<Intent>,
}

impl Response {
    /// Not this component's event.
    pub fn ignored() -> Response {
        Response::default()
    }
    /// Taken, picture changed.
    pub fn redraw() -> Response {
        Response {
            consumed: true,
            redraw: true,
            intents: Vec::new(),
        }
    }
    /// Taken, picture unchanged.
    pub fn taken() -> Response {
        Response {
            consumed: true,
            ..Response::default()
        }
    }
    pub fn with(mut self, i: Intent) -> Response {
        self.intents.push(i);
        self.redraw = true;
        self
    }
}
