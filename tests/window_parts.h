#pragma once
// How the tests reach the window's parts: by type and object name, as findChild does, so that
// the window keeps no getters for them. In the window's namespace, where calls on a window find
// them by argument-dependent lookup.

#include "ui/dialogs/image_export.h"
#include "ui/dialogs/video_export.h"
#include "ui/docks/ball_story_dock.h"
#include "ui/docks/energy_plot.h"
#include "ui/editor/editor_tools.h"
#include "ui/editor/scene_recovery.h"
#include "ui/main_window.h"
#include "ui/status_readout.h"
#include "ui/watch_alert.h"
#include "ui/watch_menu.h"

#include <QStatusBar>

namespace carom::ui {

inline editor::EditorTools* editorTools(const MainWindow& window) {
  return window.findChild<editor::EditorTools*>("editorTools");
}
inline editor::SceneRecovery* sceneRecovery(const MainWindow& window) {
  return window.findChild<editor::SceneRecovery*>("sceneRecovery");
}
inline EnergyPlot* energyPlot(const MainWindow& window) {
  return window.findChild<EnergyPlot*>("energyPlot");
}
inline BallStoryDock* ballStoryDock(const MainWindow& window) {
  return window.findChild<BallStoryDock*>("ballStoryDock");
}
inline ImageExport* imageExport(const MainWindow& window) {
  return window.findChild<ImageExport*>("imageExport");
}
inline VideoExport* videoExport(const MainWindow& window) {
  return window.findChild<VideoExport*>("videoExport");
}
inline WatchMenu* watchMenu(const MainWindow& window) {
  return window.findChild<WatchMenu*>("watchMenu");
}
// The dialog of the last event the watch stopped the run on, while it is open.
inline QMessageBox* watchDialog(const MainWindow& window) {
  return window.findChild<WatchAlert*>("watchAlert")->dialog();
}
// The status bar's passing message (refusals, saves), as opposed to the status line.
inline QString statusMessage(const MainWindow& window) {
  return window.statusBar()->currentMessage();
}
inline StatusReadout* statusReadout(const MainWindow& window) {
  return window.findChild<StatusReadout*>("statusReadout");
}
inline QString statusText(const MainWindow& window) {
  return statusReadout(window)->text();
}
// Frames drawn and snapshots shown so far.
inline int framesRendered(const MainWindow& window) {
  return statusReadout(window)->framesRendered();
}

}  // namespace carom::ui
