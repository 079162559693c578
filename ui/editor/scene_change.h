#pragma once
// What one edit did to the scene, as the document reports it to its observers.

#include "ui/editor/object_ref.h"

namespace carom::editor {

// What one change did to the scene, for observers that update only what changed. Removals
// come first, by their places in the scene before; then insertions, by their places after;
// `edited` objects changed in place and are named by their places after.
struct SceneChange {
  bool world = false;     // the world's settings
  bool replaced = false;  // a different scene (New, Open): nothing carries over
  Selection removed;
  Selection inserted;
  Selection edited;

  bool objectsChanged() const {
    return replaced || !removed.empty() || !inserted.empty() || !edited.empty();
  }
};

}  // namespace carom::editor
