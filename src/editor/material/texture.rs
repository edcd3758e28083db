//! Replacing a material's texture from the panel (issue 12): `Load`
//! opens the file browser on image files, the chosen file is read by the
//! shell (`Request::ReadTexture`, decoded like a texture a scene file
//! names: same formats, same size limits) and the answer puts the image
//! on the material as one undo step. A material that had a texture keeps
//! its wrap, transform and lighting model (only the image changes); one
//! without gets a plain repeating texture. A file that cannot be read
//! leaves the browser open with the reason, as opening a scene does.

use crate::editor::browser::{Browser, Purpose};
use crate::editor::command::Command;
use crate::editor::request::{ReadImage, Request};
use crate::editor::Editor;
use crate::format::textures::cannot_read;
use crate::scene::{ImageSource, MaterialId, Texture};
use std::path::{Path, PathBuf};

impl Editor {
    /// `Load` in the texture row: the browser on image files, in the
    /// current texture's folder, else the scene's.
    pub(in crate::internals::editor) fn browse_texture(&mut self) {
        let Some(sh) = self.material_panel() else {
            return;
        };
        let m = &self.scene.materials[sh.material.0 as usize];
        let from_texture = m
            .texture
            .as_ref()
            .and_then(|t| self.scene.image(t.image))
            .and_then(|img| match &img.source {
                ImageSource::File { path, .. } => path.parent().map(Path::to_path_buf),
                ImageSource::Inline => None,
            });
        let dir = from_texture
            .or_else(|| {
                self.path
                    .as_ref()
                    .and_then(|p| p.parent())
                    .map(Path::to_path_buf)
            })
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or_else(|| self.places.start.clone());
        let home = self.places.home.as_deref();
        self.browser = Some(Browser::new(Purpose::Texture, &dir, home));
        self.browser_then = None;
        self.set_status(
            "Choose an image (PNG, JPEG, GIF, BMP, SGI) for the texture; Esc cancels",
            false,
        );
    }

    /// The browser chose `path`: asks the shell to read it for the shown
    /// material.
    pub(in crate::internals::editor) fn ask_texture(&mut self, path: PathBuf) {
        match self.material_panel() {
            Some(sh) => self.requests.push(Request::ReadTexture {
                path,
                material: sh.material,
            }),
            None => {
                self.browser = None;
                self.set_status("No material is shown to take the texture", true);
            }
        }
    }

    /// The shell read `path` for `material`: the image goes on it (one
    /// undo step) and the browser closes, or the browser says why not.
    pub fn texture_read(&mut self, path: &Path, material: MaterialId, r: ReadImage) {
        let shown = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_else(|| path.display().to_string());
        let fail = |ed: &mut Editor, why: &str| {
            let msg = cannot_read(&shown, why);
            if let Some(b) = &mut ed.browser {
                b.message = Some(msg.clone());
            }
            ed.set_status(&msg, true);
        };
        let image = match r {
            Ok(img) => img,
            Err(e) => return fail(self, &e),
        };
        if self.scene.materials.get(material.0 as usize).is_none() {
            return fail(self, "the material is gone");
        }
        let (w, h) = (image.width(), image.height());
        let mut after = self.scene.clone();
        let id = match after.add_image(image) {
            Ok(id) => id,
            Err(e) => return fail(self, &e.to_string()),
        };
        let m = &mut after.materials[material.0 as usize];
        match &mut m.texture {
            Some(t) => t.image = id,
            None => m.texture = Some(Texture::new(id)),
        }
        self.browser = None;
        self.stop_playback();
        let name = self.material_name(material);
        let label = format!("{name}: texture {shown} ({w}x{h})");
        self.execute(
            &label,
            Command::ReplaceScene {
                before: Box::new(self.scene.clone()),
                after: Box::new(after),
            },
        );
        self.set_status(&format!("{label} (Ctrl+Z undoes)"), false);
    }
}
