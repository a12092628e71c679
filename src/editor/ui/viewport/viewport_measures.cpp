// The viewport's measures of what it shows: the bytes its frames and textures hold (the
// `memory` script line) and the histogram of the displayed image (the View panel, `stats`).
#include <cstdint>

#include "editor/ui/viewport/viewport.h"

namespace gloss {

namespace {

std::uint64_t image_bytes(const Image& image) {
  return image.pixels.size() * sizeof(glm::vec3);
}

std::uint64_t frame_images_bytes(const RenderedFrame* frame) {
  if (frame == nullptr) return 0;
  const TermImages& t = frame->images;
  return image_bytes(t.emissive) + image_bytes(t.ambient) + image_bytes(t.diffuse) +
         image_bytes(t.specular) + image_bytes(t.total);
}

// RGB32F: 12 bytes per texel as uploaded (the driver may pad).
std::uint64_t float_texture_bytes(const GlTexture& t) {
  return t.empty() ? 0 : static_cast<std::uint64_t>(t.width()) * t.height() * 12;
}

}  // namespace

std::uint64_t Viewport::frame_bytes() const {
  // The newest frames and the newest with a total image; each frame counted once.
  const RenderedFrame* held[] = {m_frame_a.get(), m_frame_b.get(), m_image_a.get(),
                                 m_image_b.get()};
  std::uint64_t total = 0;
  for (int i = 0; i < 4; ++i) {
    if (std::find(held, held + i, held[i]) == held + i) total += frame_images_bytes(held[i]);
  }
  return total;
}

std::uint64_t Viewport::texture_bytes() const {
  std::uint64_t total = 0;
  for (const GlTexture* t :
       {&m_total, &m_emissive, &m_ambient, &m_diffuse, &m_specular, &m_b_total}) {
    total += float_texture_bytes(*t);
  }
  // The off-screen target the panes are drawn into: RGBA8.
  return total + static_cast<std::uint64_t>(m_target.width()) * m_target.height() * 4;
}

ExposureHistogram Viewport::histogram(const ViewSettings& view, const DisplayTransform& display,
                                      bool exact) {
  const bool live_is_b = view.mode == ViewMode::ab && view.ab_source == AbSource::snapshot;
  const RenderedFrame* frame = live_is_b ? m_image_b.get() : m_image_a.get();
  if (frame == nullptr) return {};
  TermView term = view.mode == ViewMode::single ? view.single : TermView::total;
  if (frame->images.emissive.width == 0) term = TermView::total;  // terms not rendered yet
  const HistogramKey key{frame, display.gain, display.tone, display.srgb, exact, term};
  if (key == m_histogram_key) return m_histogram;
  const TermImages& images = frame->images;
  const Image* image = &images.total;
  Image sum;
  switch (term) {
    case TermView::emissive_ambient:
      sum = images.emissive;
      for (std::size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += images.ambient.pixels[i];
      image = &sum;
      break;
    case TermView::emissive:
      image = &images.emissive;
      break;
    case TermView::ambient:
      image = &images.ambient;
      break;
    case TermView::diffuse:
      image = &images.diffuse;
      break;
    case TermView::specular:
      image = &images.specular;
      break;
    case TermView::total:
      break;
  }
  // At most about 16k samples in the bins (every step-th pixel of every step-th row): the
  // histogram costs about 0.2 ms per new frame instead of 1 ms at 65k (perf during a slider
  // drag: a quarter of the UI thread's time). The clipped pixels are counted in every pixel.
  const double pixels = static_cast<double>(image->width) * image->height;
  const int step =
      exact ? 1 : std::max(1, static_cast<int>(std::ceil(std::sqrt(pixels / 16384.0))));
  m_histogram = exposure_histogram(*image, display, step);
  m_histogram_key = key;
  return m_histogram;
}

}  // namespace gloss
