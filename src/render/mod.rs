//! The CPU rasteriser: clipping, fixed-point edge functions, per-pixel
//! VRML97 lighting, deterministic tiled threading.
