#!/usr/bin/python3
"""Run a Coin render tool with every text given the face animed draws it in.

Used by tests/coin_corpus.sh (issue 19, item 5). animed draws text with the
Liberation faces (assets/fonts/README.md: Times New Roman, Arial and Courier
New metrics); with Debian's fonts-liberation2 installed, fontconfig maps
"Times New Roman", "Arial" and "Courier New" to exactly those faces. Coin 4.0
loads FreeType and fontconfig at run time, but left alone it draws most text
in another font than the file asks for:

(a) VRML97 Text ignores FontStyle.family and .style. In Coin's
    src/vrml97/Text.cpp, SoVRMLTextP::setUpGlyphs builds `fontstr`
    ("Times New Roman" / "Arial" / "Courier New" + ":Bold" ...) and never
    uses it: the glyphs come from the fontspec read from the state's
    SoFontNameElement (`this->cache->readFontspec(state)` just above), whose
    default "defaultFont" is Coin's built-in font. VRML97 6.20 asks for a
    serif face for SERIF and a fixed-pitch one for TYPEWRITER.
(b) Inventor and VRML 1.0 text with no font name uses that same
    "defaultFont", where SGI Inventor's SoFont name defaults to
    "Times-Roman" (The Inventor Mentor, SoFont) and VRML 1.0 FontStyle's
    family to SERIF (Coin's own SoFontStyle::getFontName gives FontStyle
    nodes "Times New Roman"; a file without one gets "defaultFont"). And
    text under no Font at all is 12 units in Coin, 10 in SGI Inventor and
    VRML 1.0: Coin's SoFontSizeElement::getDefault() returns 12 ("Default
    size now equal to size of default font (12)", Coin commit 40d11c6615,
    2003), SGI's 10, and Coin's own SoFont.size still defaults to 10.
(c) Inventor's PostScript names go to FcNameParse unchanged
    (src/fonts/freetype.cpp find_font_file); fontconfig's name syntax reads
    "Courier-Bold" as family Courier at size "Bold", so the face is the
    regular one (`fc-match Courier-Bold` vs `fc-match Courier:Bold`).

So that the silhouettes compare text layout and size rather than the font
choice, this script wraps pivy's SoDB.readAll (like coin_render_nobg.py,
which it composes with) and, in the graph read:
- puts an SoFont naming the VRML97 family/style's face (Coin's own `fontstr`
  names, (a)) in front of every VRML97 Shape whose geometry is a Text, in the
  Shape's parent: Coin's SoVRMLText reads its glyphs from that state;
- names every Inventor Font node the face animed gives its name
  (src/format/text/mod.rs inventor_font: Courier/mono -> Courier New,
  Helvetica/Arial/sans -> Arial, else Times New Roman; "bold", "italic" or
  "oblique" in the name -> :Bold / :Italic), (b) and (c);
- puts an SoFont "Times New Roman", size 10, first in the root, for
  Inventor and VRML 1.0 text under no Font at all, (b).
VRML 1.0 FontStyle nodes are left alone: Coin names their faces already.
Each Font keeps its size field as read; the ones put before VRML97 Shapes set
no size (VRML97 Text takes its size from FontStyle).

usage: coin_render_font.py TOOL in out.png [TOOL's other arguments]
Prints what it did ("font: ...") to stderr, so the log says so.
"""
import sys

from pivy import coin

from coin_graph_edit import edit_graph_on_read, run_tool

# animed's families (src/format/text/mod.rs) and the fontconfig names that
# reach its Liberation faces; the VRML97 names are Coin's own `fontstr`.
FACES = {"SERIF": "Times New Roman", "SANS": "Arial", "TYPEWRITER": "Courier New"}
STYLES = {"PLAIN": "", "BOLD": ":Bold", "ITALIC": ":Italic", "BOLDITALIC": ":Bold Italic"}


def vrml97_face(fontstyle):
    """The fontconfig name for a VRML97 FontStyle (None: defaults), as animed
    reads it: the first family it knows (6.20.2), else SERIF; style PLAIN
    unless one of the four words."""
    family, style = "SERIF", "PLAIN"
    if fontstyle is not None:
        fams = [fontstyle.family[i].getString() for i in range(fontstyle.family.getNum())]
        family = next((f for f in fams if f in FACES), "SERIF")
        styles = [fontstyle.style[i].getString() for i in range(fontstyle.style.getNum())]
        if styles and styles[0] in STYLES:
            style = styles[0]
    return FACES[family] + STYLES[style]


def inventor_face(name):
    """The fontconfig name of the face animed draws an Inventor Font name in
    (src/format/text/mod.rs inventor_font)."""
    low = name.lower()
    if any(k in low for k in ("courier", "mono", "typewriter", "fixed")):
        face = "Courier New"
    elif any(k in low for k in ("helvetica", "arial", "sans", "verdana", "utopia")):
        face = "Arial"
    else:
        face = "Times New Roman"
    bold = "bold" in low
    italic = "italic" in low or "oblique" in low
    return face + {(False, False): "", (True, False): ":Bold",
                   (False, True): ":Italic", (True, True): ":Bold Italic"}[(bold, italic)]


def paths_to(scene, type_name, derived=True):
    ty = coin.SoType.fromName(coin.SbName(type_name))
    if ty.isBad():
        return []
    sa = coin.SoSearchAction()
    sa.setType(ty, derived)
    sa.setInterest(coin.SoSearchAction.ALL)
    sa.setSearchingAll(True)
    sa.apply(scene)
    ps = sa.getPaths()
    return [ps[i].copy() for i in range(ps.getLength())]


def name_font(face):
    f = coin.SoFont()
    f.name.setValue(face)
    f.size.setIgnored(True)
    return f


def give_fonts(scene):
    done = []
    # (b), (c) Inventor Font nodes (not FontStyle, which Coin names itself).
    for p in paths_to(scene, "Font", derived=False):
        f = p.getTail()
        if f.name.isIgnored():
            continue
        was = f.name.getValue().getString()
        face = inventor_face(was if not f.name.isDefault() else "Times-Roman")
        f.name.setValue(face)
        done.append("Font %r -> %s" % (was, face))
    # (a) VRML97 Text: a Font in front of its Shape.
    shape_t = coin.SoType.fromName(coin.SbName("VRMLShape"))
    text_t = coin.SoType.fromName(coin.SbName("VRMLText"))
    seen = set()
    for p in paths_to(scene, "VRMLText"):
        k = next((i for i in range(p.getLength() - 1, 0, -1)
                  if p.getNode(i).isOfType(shape_t)), None)
        if k is None:
            continue
        parent, shape = p.getNode(k - 1), p.getNode(k)
        key = (int(parent.this), int(shape.this))
        idx = parent.findChild(shape)
        if idx < 0 or key in seen:
            continue
        seen.add(key)
        # Coin's search ends the path at the Shape (its geometry is a
        # field, not a child).
        text = shape.geometry.getValue()
        if text is None or not text.isOfType(text_t):
            continue
        face = vrml97_face(text.fontStyle.getValue())
        parent.insertChild(name_font(face), idx)
        done.append("VRML97 Text -> %s" % face)
    # (b) Inventor / VRML 1.0 text under no Font: SGI's defaults, Times-Roman
    # at 10 (Coin's SoFontSizeElement default is 12, its SoFont.size 10).
    root = name_font("Times New Roman")
    root.size.setIgnored(False)
    root.size.setValue(10.0)
    scene.insertChild(root, 0)
    done.append("root -> Times New Roman, size 10")
    return done


def report_fonts(scene):
    for line in give_fonts(scene):
        print("font: " + line, file=sys.stderr)


edit_graph_on_read(report_fonts)

if __name__ == "__main__":
    run_tool()
