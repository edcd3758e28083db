/// How the segment that *starts* at a key is interpolated.
///
/// For rotations `Linear` is slerp and `Tcb` is squad with Kochanek-Bartels
/// intermediate quaternions; for booleans every segment is a step.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Interp {
    Step,
    Linear,
    #[default]
    Tcb,
}

impl Interp {
    /// Parses the names used on the command line and in the export note:
    /// `step`, `linear`, `tcb`, and the rotation names `slerp` (= linear) and
    /// `squad` (= tcb).
    pub fn parse(s: &str) -> Option<Interp> {
        match s.to_ascii_lowercase().as_str() {
            "step" | "constant" => Some(Interp::Step),
            "linear" | "slerp" => Some(Interp::Linear),
            "tcb" | "spline" | "squad" => Some(Interp::Tcb),
            _ => None,
        }
    }

    /// Canonical name; rotations say slerp/squad.
    pub fn name(self, rotation: bool) -> &'static str {
        match (self, rotation) {
            (Interp::Step, _) => "step",
            (Interp::Linear, false) => "linear",
            (Interp::Linear, true) => "slerp",
            (Interp::Tcb, false) => "tcb",
            (Interp::Tcb, true) => "squad",
        }
    }
}

/// One key: a value at a frame, and how to leave it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Key<V> {
    /// Time in frames.
    pub frame: f32,
    pub value: V,
    pub interp: Interp,
    /// Kochanek-Bartels tension, continuity, bias, each in [-1, 1].
    pub tension: f32,
    pub continuity: f32,
    pub bias: f32,
    /// 3ds Max "ease to" (arriving at this key) and "ease from" (leaving it),
    /// each in [0, 1]: a time remap that slows motion near the key.
    pub ease_in: f32,
    pub ease_out: f32,
}

impl<V> Key<V> {
    pub fn new(frame: f32, value: V) -> Self {
        Key {
            frame,
            value,
            interp: Interp::Tcb,
            tension: 0.0,
            continuity: 0.0,
            bias: 0.0,
            ease_in: 0.0,
            ease_out: 0.0,
        }
    }

    pub fn with_interp(mut self, interp: Interp) -> Self {
        self.interp = interp;
        self
    }

    pub fn with_tcb(mut self, t: f32, c: f32, b: f32) -> Self {
        self.tension = t;
        self.continuity = c;
        self.bias = b;
        self
    }
}

/// Everything about a key except its time and value: what the editor's key
/// panel and `animed key` edit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct KeyParams {
    pub interp: Interp,
    pub tension: f32,
    pub continuity: f32,
    pub bias: f32,
    pub ease_in: f32,
    pub ease_out: f32,
}

impl Default for KeyParams {
    fn default() -> Self {
        let k = Key::new(0.0, ());
        k.params()
    }
}

impl<V> Key<V> {
    pub fn params(&self) -> KeyParams {
        KeyParams {
            interp: self.interp,
            tension: self.tension,
            continuity: self.continuity,
            bias: self.bias,
            ease_in: self.ease_in,
            ease_out: self.ease_out,
        }
    }

    pub fn with_params(mut self, p: KeyParams) -> Self {
        self.interp = p.interp;
        self.tension = p.tension;
        self.continuity = p.continuity;
        self.bias = p.bias;
        self.ease_in = p.ease_in;
        self.ease_out = p.ease_out;
        self
    }

    pub fn with_ease(mut self, ease_in: f32, ease_out: f32) -> Self {
        self.ease_in = ease_in;
        self.ease_out = ease_out;
        self
    }

    /// The same key with its value converted.
    pub fn map<W>(self, f: impl FnOnce(V) -> W) -> Key<W> {
        Key {
            frame: self.frame,
            value: f(self.value),
            interp: self.interp,
            tension: self.tension,
            continuity: self.continuity,
            bias: self.bias,
            ease_in: self.ease_in,
            ease_out: self.ease_out,
        }
    }
}
