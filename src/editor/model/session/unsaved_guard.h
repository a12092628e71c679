#pragma once
// The question asked before opening another scene would drop unsaved edits: save, discard or
// cancel. The UI shows it as a modal; this holds its state so the rules are testable without one.
#include <string>

namespace gloss {

enum class UnsavedAnswer { save, discard, cancel };

class UnsavedGuard {
 public:
  // What the caller does after an answer. save_first: save the document to its path, and open
  // only if that succeeded. open: open 'path'.
  struct Outcome {
    bool save_first = false;
    bool open = false;
    std::string path;
  };

  // Asks to open path. When the document has no unsaved changes the open may run at once
  // (returns true); else the question opens, path waits for answer(), and this returns false.
  // A second request while the question is open replaces the waiting path.
  bool request_open(const std::string& path, bool dirty);

  bool asking() const { return m_asking; }
  const std::string& waiting_path() const { return m_path; }

  // The user's answer; the question closes. Answering when nothing is asked gives no outcome.
  Outcome answer(UnsavedAnswer answer);

 private:
  bool m_asking = false;
  std::string m_path;
};

}  // namespace gloss
