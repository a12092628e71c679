#pragma once
// Parts of the Quality window (quality_panel.cpp) kept in files of their own: the raster (GLSL)
// rows of issue 12 and the plot of every row, error against time.
#include <imgui.h>

namespace gloss {

class Commands;
struct OpenWindows;
struct QualityState;
struct Scene;

// Frames' budget of raster measuring on the UI thread, milliseconds: the window stays usable
// (a few frames a second) while the raster rows are measured.
inline constexpr double kRasterQualitySliceMs = 60.0;

// The "Raster (GLSL)" tab: its Measure / Cancel button, progress, table, plot and notes.
void draw_raster_quality_section(QualityState& quality, OpenWindows& windows, Commands& commands);

// Error (RMSE, log) against time (ms, log) of the CPU rows and the raster rows measured so far,
// one colour per knob family; hovering a point names its row. Nothing when there are no rows.
void draw_quality_plot(const QualityState& quality, float height);

// Starts the raster rows' measurement of scene at the Quality window's quick size and reference,
// or with the given size (width and height > 0) and reference spp (> 0), and shows the window's
// raster tab. Throws std::invalid_argument for options out of range.
void start_raster_quality(QualityState& quality, OpenWindows& windows, const Scene& scene,
                          int width = 0, int height = 0, int reference_spp = 0);

}  // namespace gloss
