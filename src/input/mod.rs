//! The input vocabulary shared by every screen: events ([`Event`], [`Key`],
//! [`Mods`]), the [`Screen`] trait the window loop drives, and the orbit
//! camera both the editor and the viewer turn with the mouse. A leaf: it
//! knows nothing of the editor, the viewer or the window (`app` adapts
//! minifb to it; scripts build events from text).

pub mod camera;
mod event;
mod screen;

pub use camera::{OrbitCamera, Projector};
pub use event::{Event, Key, Mods, MouseButton};
pub use screen::Screen;
