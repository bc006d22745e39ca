#include "render/cairo_canvas.h"

#include <cairo-ft.h>
#include <pango/pangocairo.h>
#include <pango/pangofc-font.h>

#include <cstring>
#include <map>
#include <utility>

#include <fmt/format.h>

#include "render/font_metrics.h"
#include "render/text.h"
#include "render/utf8.h"

namespace epure::render {
namespace {

// Shaped runs kept per canvas; past this many the cache starts again, so memory stays flat
// however many sheets one canvas draws.
constexpr std::size_t kMaxShaped = 1024;

void set_colour(cairo_t* cr, Colour c) { cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0); }

void trace(cairo_t* cr, const Path& path) {
  cairo_new_path(cr);
  for (const Path::Cmd& c : path.cmds()) {
    switch (c.op) {
      case Path::Op::move: cairo_move_to(cr, c.p[0].x, c.p[0].y); break;
      case Path::Op::line: cairo_line_to(cr, c.p[0].x, c.p[0].y); break;
      case Path::Op::cubic:
        cairo_curve_to(cr, c.p[0].x, c.p[0].y, c.p[1].x, c.p[1].y, c.p[2].x, c.p[2].y);
        break;
      case Path::Op::close: cairo_close_path(cr); break;
    }
  }
}

// The user data that ties a face's FreeType library to the cairo face made from it: cairo keeps
// faces in its caches after the canvas is gone, and frees the library when it lets go.
const cairo_user_data_key_t kOwnLibrary{};

// The font file `file` opened in a FreeType library of its own, as a cairo face; null when it
// cannot be opened.
cairo_font_face_t* open_face(const char* file, int index) {
  FT_Library library = nullptr;
  if (FT_Init_FreeType(&library) != 0) return nullptr;
  FT_Face ft = nullptr;
  if (FT_New_Face(library, file, index, &ft) != 0) {
    FT_Done_FreeType(library);
    return nullptr;
  }
  cairo_font_face_t* face = cairo_ft_font_face_create_for_ft_face(ft, 0);
  // FT_Done_FreeType frees the face with its library, once cairo has let go of both
  if (cairo_font_face_set_user_data(face, &kOwnLibrary, library,
                                    [](void* l) { FT_Done_FreeType(static_cast<FT_Library>(l)); }) !=
      CAIRO_STATUS_SUCCESS) {
    cairo_font_face_destroy(face);
    FT_Done_FreeType(library);
    return nullptr;
  }
  return face;
}

// The faces opened on this thread, by file: the documents a thread draws one after the other
// (a sheet's PDF, then its key's) share their faces, so cairo's scaled fonts and the glyphs
// they hold are made once a thread, not once a document.
struct ThreadFaces {
  std::map<std::pair<std::string, int>, cairo_font_face_t*> faces;
  ThreadFaces() = default;
  ThreadFaces(const ThreadFaces&) = delete;
  ThreadFaces& operator=(const ThreadFaces&) = delete;
  ~ThreadFaces() {
    for (auto& [file, face] : faces) cairo_font_face_destroy(face);
  }
};

// The font file pango chose for `font`, as a cairo face of the calling thread's (a reference
// the caller owns), or null (then pango's face, `shared`, is used): also when pango's face is
// more than the file, a bold made up from the regular (fontconfig's embolden, where no bold file
// is installed) or a variable font's instance, which the file opened alone would not draw.
// cairo keys the faces it makes from fontconfig by file, so two canvases drawing DejaVu Sans on
// two threads would otherwise share one face and its scaled fonts, whose locks every glyph
// takes: issue 34 measured 7,326 futex calls on 100 sheets of two jobs, 1,643 with faces of
// the thread's.
cairo_font_face_t* thread_face(PangoFont* font, cairo_font_face_t* shared) {
  if (!PANGO_IS_FC_FONT(font) || cairo_font_face_get_type(shared) != CAIRO_FONT_TYPE_FT ||
      cairo_ft_font_face_get_synthesize(shared) != 0)
    return nullptr;
  FcPattern* pattern = pango_fc_font_get_pattern(PANGO_FC_FONT(font));
  FcChar8* file = nullptr;
  FcChar8* variations = nullptr;
  int index = 0;
  if (pattern == nullptr || FcPatternGetString(pattern, FC_FILE, 0, &file) != FcResultMatch ||
      FcPatternGetString(pattern, FC_FONT_VARIATIONS, 0, &variations) == FcResultMatch)
    return nullptr;
  FcPatternGetInteger(pattern, FC_INDEX, 0, &index);
  thread_local ThreadFaces opened;
  auto key = std::make_pair(std::string(reinterpret_cast<const char*>(file)), index);
  auto it = opened.faces.find(key);
  if (it == opened.faces.end()) {
    cairo_font_face_t* face = open_face(key.first.c_str(), index);
    if (face == nullptr) return nullptr;
    it = opened.faces.emplace(std::move(key), face).first;
  }
  return cairo_font_face_reference(it->second);
}

}  // namespace

CairoCanvas::CairoCanvas(cairo_t* cr, PangoFontMap* fonts)
    : cr_(cr),
      own_faces_(fonts != nullptr),
      context_(fonts != nullptr ? pango_font_map_create_context(fonts) : pango_cairo_create_context(cr)) {
  if (fonts != nullptr) pango_cairo_update_context(cr_, context_);
  // Unhinted outlines and advances: text is set at the widths font_metrics.h measured, on every
  // surface and at every zoom.
  cairo_font_options_t* options = cairo_font_options_create();
  cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
  cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_NONE);
  pango_cairo_context_set_font_options(context_, options);
  font_options_ = options;
  // One user-space unit is a point: a font size in points is a size in user units.
  pango_cairo_context_set_resolution(context_, 72);
  // Pango rounds glyph positions to whole units by default, here whole points: letters would
  // wobble and lines grow by up to a point a glyph.
  pango_context_set_round_glyph_positions(context_, FALSE);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_MITER);
  cairo_set_line_cap(cr_, CAIRO_LINE_CAP_BUTT);  // SVG's defaults, so both backends agree
  cairo_set_miter_limit(cr_, 4);
}

CairoCanvas::~CairoCanvas() {
  flush_text();
  for (auto& [key, layout] : shaped_) g_object_unref(layout);
  for (LoadedFace& f : faces_) {
    if (f.face != nullptr) cairo_font_face_destroy(f.face);
    if (f.font != nullptr) g_object_unref(f.font);
  }
  cairo_font_options_destroy(font_options_);
  g_object_unref(context_);
}

// Groups are SVG's semantics (classes for a style sheet or a reader); a PDF page has no use for
// them, and cairo_push_group would rasterise nothing but cost a copy.
void CairoCanvas::begin_group(std::string_view, std::string_view) {}
void CairoCanvas::end_group() {}

void CairoCanvas::push_clip(const Box& box) {
  flush_text();
  cairo_save(cr_);
  cairo_new_path(cr_);
  cairo_rectangle(cr_, box.x_min, box.y_min, box.width(), box.height());
  cairo_clip(cr_);
}

void CairoCanvas::pop_clip() {
  flush_text();
  cairo_restore(cr_);
}

void CairoCanvas::fill_and_stroke(const Paint& paint) {
  if (paint.fill) {
    const Colour c = *paint.fill;
    if (paint.fill_opacity < 1)
      cairo_set_source_rgba(cr_, c.r / 255.0, c.g / 255.0, c.b / 255.0, paint.fill_opacity);
    else
      set_colour(cr_, c);
    if (paint.stroke) cairo_fill_preserve(cr_);
    else cairo_fill(cr_);
  }
  if (paint.stroke) {
    set_colour(cr_, paint.stroke->colour);
    cairo_set_line_width(cr_, paint.stroke->width);
    const auto& dash = paint.stroke->dash;
    cairo_set_dash(cr_, dash.empty() ? nullptr : dash.data(), static_cast<int>(dash.size()), 0);
    cairo_stroke(cr_);
  }
  cairo_new_path(cr_);
}

void CairoCanvas::path(const Path& path, const Paint& paint) {
  if (path.empty()) return;
  flush_text();
  trace(cr_, path);
  fill_and_stroke(paint);
}

namespace {

// cairo reads a PNG through a callback: this one from bytes in memory.
struct PngBytes {
  const std::string* bytes;
  std::size_t at = 0;
};

cairo_status_t read_png_bytes(void* closure, unsigned char* data, unsigned int length) {
  auto* in = static_cast<PngBytes*>(closure);
  if (in->bytes->size() - in->at < length) return CAIRO_STATUS_READ_ERROR;
  std::memcpy(data, in->bytes->data() + in->at, length);
  in->at += length;
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

// Bytes cairo cannot decode draw nothing: the crop is an aid beside the verdict, and a page is
// not lost for it (the reader, support/png_size.h, has already refused what is not a PNG).
void CairoCanvas::image(const Raster& raster, const Box& box) {
  if (raster.empty()) return;
  flush_text();
  PngBytes in{raster.png.get()};
  cairo_surface_t* png = cairo_image_surface_create_from_png_stream(read_png_bytes, &in);
  if (cairo_surface_status(png) == CAIRO_STATUS_SUCCESS) {
    const int w = cairo_image_surface_get_width(png), h = cairo_image_surface_get_height(png);
    if (w > 0 && h > 0) {
      cairo_save(cr_);
      cairo_translate(cr_, box.x_min, box.y_min);
      cairo_scale(cr_, box.width() / w, box.height() / h);
      cairo_set_source_surface(cr_, png, 0, 0);
      cairo_pattern_set_filter(cairo_get_source(cr_), CAIRO_FILTER_GOOD);
      cairo_paint(cr_);
      cairo_restore(cr_);
    }
  }
  cairo_surface_destroy(png);
}

void CairoCanvas::disc(P2 centre, double radius, const Paint& paint) {
  flush_text();
  cairo_new_path(cr_);
  cairo_arc(cr_, centre.x, centre.y, radius, 0, 2 * 3.14159265358979323846);
  cairo_close_path(cr_);
  fill_and_stroke(paint);
}

PangoLayout* CairoCanvas::shaped(const TextRun& run, double size) {
  std::string key = fmt::format("{}|{:.4f}|{}", run.bold ? 'b' : 'r', size, run.text);
  if (auto it = shaped_.find(key); it != shaped_.end()) return it->second;
  if (shaped_.size() >= kMaxShaped) {
    for (auto& [k, layout] : shaped_) g_object_unref(layout);
    shaped_.clear();
  }
  PangoLayout* layout = pango_layout_new(context_);
  PangoFontDescription* font = pango_font_description_new();
  pango_font_description_set_family_static(font, "DejaVu Sans");
  pango_font_description_set_weight(font, run.bold ? PANGO_WEIGHT_BOLD : PANGO_WEIGHT_NORMAL);
  pango_font_description_set_absolute_size(font, size * PANGO_SCALE);
  pango_layout_set_font_description(layout, font);
  pango_font_description_free(font);
  // No kerning nor ligatures: the widths are font_metrics.h's, glyph by glyph.
  PangoAttrList* attrs = pango_attr_list_new();
  pango_attr_list_insert(attrs, pango_attr_font_features_new("kern 0, liga 0, clig 0"));
  pango_layout_set_attributes(layout, attrs);
  pango_attr_list_unref(attrs);
  pango_layout_set_text(layout, run.text.data(), static_cast<int>(run.text.size()));
  shaped_.emplace(std::move(key), layout);
  return layout;
}

double CairoCanvas::set_width(const TextRun& run, double size) {
  PangoRectangle logical;
  pango_layout_get_extents(shaped(run, size), nullptr, &logical);
  return logical.width / static_cast<double>(PANGO_SCALE);
}

CairoCanvas::LoadedFace& CairoCanvas::face(bool bold) {
  LoadedFace& f = faces_[bold ? 1 : 0];
  if (f.font == nullptr) {
    PangoFontDescription* font = pango_font_description_new();
    pango_font_description_set_family_static(font, "DejaVu Sans");
    pango_font_description_set_weight(font, bold ? PANGO_WEIGHT_BOLD : PANGO_WEIGHT_NORMAL);
    pango_font_description_set_absolute_size(font, 10 * PANGO_SCALE);
    f.font = pango_context_load_font(context_, font);
    pango_font_description_free(font);
    if (f.font != nullptr && PANGO_IS_CAIRO_FONT(f.font)) {
      f.scaled = pango_cairo_font_get_scaled_font(PANGO_CAIRO_FONT(f.font));
      if (f.scaled != nullptr && own_faces_) f.face = thread_face(f.font, cairo_scaled_font_get_font_face(f.scaled));
      if (f.scaled != nullptr && f.face == nullptr)
        f.face = cairo_font_face_reference(cairo_scaled_font_get_font_face(f.scaled));
    }
  }
  return f;
}

bool CairoCanvas::set_glyphs(const TextRun& run, double size, double x, double baseline, Colour colour) {
  LoadedFace& f = face(run.bold);
  if (f.face == nullptr) return false;
  // Another face, size or colour needs other operators first (Tf, rg): what is held is drawn.
  // The size is compared exactly: any other value is another font matrix to cairo.
  if (pending_.face != &f || pending_.size != size || pending_.colour != colour) flush_text();
  const std::string_view text = run.text;
  const Face face_kind = run.bold ? Face::bold : Face::regular;
  const std::size_t held = pending_.glyphs.size();
  for (std::size_t i = 0; i < text.size();) {
    const utf8::Decoded d = utf8::decode(text, i);
    auto it = f.glyphs.find(d.cp);
    if (it == f.glyphs.end()) {
      unsigned long index = 0;
      cairo_glyph_t* glyphs = nullptr;
      int count = 0;
      const std::string one(text.substr(i, d.length));
      if (d.valid && has_glyph(d.cp) &&
          cairo_scaled_font_text_to_glyphs(f.scaled, 0, 0, one.data(), static_cast<int>(one.size()), &glyphs, &count,
                                           nullptr, nullptr, nullptr) == CAIRO_STATUS_SUCCESS &&
          count == 1)
        index = glyphs[0].index;
      cairo_glyph_free(glyphs);
      it = f.glyphs.emplace(d.cp, index).first;
    }
    if (it->second == 0) {  // this run goes to pango; what was held before it stays
      pending_.glyphs.resize(held);
      pending_.clusters.resize(held);
      return false;
    }
    pending_.glyphs.push_back({it->second, x, baseline});
    pending_.clusters.push_back({static_cast<int>(d.length), 1});
    x += advance_em(d.cp, face_kind) * size;
    i += d.length;
  }
  pending_.face = &f;
  pending_.size = size;
  pending_.colour = colour;
  pending_.utf8 += text;
  return true;
}

void CairoCanvas::flush_text() {
  if (pending_.glyphs.empty()) return;
  cairo_set_font_face(cr_, pending_.face->face);
  cairo_set_font_size(cr_, pending_.size);
  cairo_set_font_options(cr_, font_options_);
  set_colour(cr_, pending_.colour);
  // With the characters each glyph stands for: a PDF's text can be searched and copied.
  cairo_show_text_glyphs(cr_, pending_.utf8.data(), static_cast<int>(pending_.utf8.size()), pending_.glyphs.data(),
                         static_cast<int>(pending_.glyphs.size()), pending_.clusters.data(),
                         static_cast<int>(pending_.clusters.size()), cairo_text_cluster_flags_t{});
  pending_.utf8.clear();
  pending_.glyphs.clear();
  pending_.clusters.clear();
}

void CairoCanvas::text(const TextLine& line) {
  const std::vector<RunPlacement> placed = place_runs(line.runs, line.size);
  double left = line.at.x;
  if (line.anchor != Anchor::start) {
    const double width = text_width(line.runs, line.size);
    left -= line.anchor == Anchor::middle ? width / 2 : width;
  }
  for (std::size_t i = 0; i < line.runs.size(); ++i) {
    const TextRun& run = line.runs[i];
    if (run.text.empty()) continue;
    const RunPlacement& p = placed[i];
    if (set_glyphs(run, p.size, left + p.x, line.at.y - p.rise, line.colour)) continue;
    flush_text();
    set_colour(cr_, line.colour);
    PangoLayout* layout = shaped(run, p.size);
    const double baseline = pango_layout_get_baseline(layout) / static_cast<double>(PANGO_SCALE);
    cairo_move_to(cr_, left + p.x, line.at.y - p.rise - baseline);
    pango_cairo_show_layout(cr_, layout);
  }
}

}  // namespace epure::render
