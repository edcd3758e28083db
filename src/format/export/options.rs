//! What a writer is asked to do and what it reports back; shared by every
//! writer and by `save`, so writers never depend on the save dispatch.

/// Which Inventor text version to write.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum InventorVersion {
    /// `#Inventor V2.1 ascii`: scene plus engine-driven animation.
    #[default]
    V2_1,
    /// `#Inventor V1.0 ascii`: the still scene (for 1.0-only readers such
    /// as view3dscene); the animation survives only in the key note.
    V1_0,
}

/// Writer settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WriteOptions {
    /// Position tolerance as a fraction of the scene's bounding-box diagonal
    /// (also the relative scale tolerance).
    pub tolerance: f32,
    /// Rotation/direction/angle tolerance in degrees.
    pub angle_tolerance: f32,
    pub inventor_version: InventorVersion,
    /// X3D output: write tracks that X3D's SplinePosition/SplineScalar/
    /// SquadOrientation interpolators carry exactly as those nodes
    /// (`x3d::spline_keys`) instead of sampled linear ones. Off by default:
    /// view3dscene 4.2 reads these nodes but does not play them.
    pub x3d_splines: bool,
}

impl Default for WriteOptions {
    fn default() -> Self {
        WriteOptions {
            tolerance: 0.001,
            angle_tolerance: 0.1,
            inventor_version: InventorVersion::V2_1,
            x3d_splines: false,
        }
    }
}

/// Per animated field: how many keys went into the file.
#[derive(Clone, Debug, PartialEq)]
pub struct ChannelReport {
    /// `NAME.field` as written.
    pub name: String,
    pub authored_keys: usize,
    pub written_keys: usize,
    /// What a per-frame bake of the same field would need.
    pub per_frame_keys: usize,
}

/// What a writer did, for `convert --verbose` and the tests.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct WriteReport {
    pub channels: Vec<ChannelReport>,
    /// Things the format cannot hold, each a sentence.
    pub warnings: Vec<String>,
}

impl WriteReport {
    pub fn written_keys(&self) -> usize {
        self.channels.iter().map(|c| c.written_keys).sum()
    }
    pub fn per_frame_keys(&self) -> usize {
        self.channels.iter().map(|c| c.per_frame_keys).sum()
    }
    pub fn authored_keys(&self) -> usize {
        self.channels.iter().map(|c| c.authored_keys).sum()
    }
}
