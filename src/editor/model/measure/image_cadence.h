#pragma once
// When new images reach the screen, and how long after the edits they show: the edit delay (from
// an edit to the swap that first shows a frame of it) and the gaps between shown images, for
// continuous edits (an orbiting light, a drag, a script of edits 16 ms apart) as for single
// ones, where each new edit used to reset the measurement before any image completed it. The
// viewport feeds it; the status bar and `stats` read it. Times are seconds on the frame clock.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>

namespace gloss {

class ImageCadence {
 public:
  // Any generation: a frame that shows the newest edit (the raster path draws synchronously).
  static constexpr std::uint64_t kNewest = std::numeric_limits<std::uint64_t>::max();

  // An edit handed to the renderer, whose frames carry `generation` (set_scene's), at now_s: the
  // start of the frame in which the edit happened. Generations ascend.
  void edit(std::uint64_t generation, double now_s);

  // The delays a shown image completes (ms; -1 when it completes none).
  struct Delays {
    double first_ms = -1;          // from its edit to the first frame of it
    double full_ms = -1;           // from its edit to the first full-size frame of it
    std::uint64_t generation = 0;  // the edit's (the frame's, or the newest for kNewest)
  };
  // A new image reached the screen at now_s (the buffer swap that showed it): a frame of
  // `generation`, full_size when it has the render's size. It is measured from the edit of its
  // own generation; older edits it also shows (steps of an animation that came faster than
  // frames) are done with, and an edit no frame showed on its own counts in no delay (the gaps
  // show that the image stood still).
  Delays shown(std::uint64_t generation, bool full_size, double now_s);

  // The edits not shown yet are dropped (they count in no delay): the frames that would show
  // them now come from another renderer, whose generations are counted apart.
  void forget_pending();

  // Figures since the window began (restart(), or the first call), now_s its end.
  struct Window {
    double seconds = 0;
    int images = 0;              // new images shown
    double max_gap_ms = 0;       // longest time without a new image: from the window's start to
                                 // the first, between two, and from the last to now_s
    double median_gap_ms = 0;    // median of those gaps
    int delays = 0;              // images that were the first of an edit
    double median_delay_ms = 0;  // edit -> its first image, their median and largest
    double max_delay_ms = 0;
  };
  Window window(double now_s) const;
  void restart(double now_s);

 private:
  struct Pending {
    std::uint64_t generation;
    double edit_s;
  };
  std::deque<Pending> m_pending;  // edits not shown yet, oldest first
  Pending m_shown{0, -1};         // the edit of the newest image, until its first full-size image
  bool m_full_done = true;
  double m_window_s = -1;       // the window's start; -1: at the first call
  std::deque<double> m_images;  // times the window's images were shown (the newest kept)
  std::deque<double> m_delays;  // the window's edit delays (ms)
};

}  // namespace gloss
