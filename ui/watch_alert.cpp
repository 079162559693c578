#include "ui/watch_alert.h"

#include "ui/editor/number_text.h"
#include "ui/editor/scene_document.h"
#include "ui/render/scene_view.h"
#include "ui/run/simulation_controller.h"
#include "ui/run/simulation_snapshot.h"
#include "ui/watch_text.h"

#include <QMainWindow>
#include <QMessageBox>
#include <QPushButton>
#include <QStatusBar>

namespace carom::ui {

WatchAlert::WatchAlert(editor::SceneDocument* document, render::SceneView* view,
                       SimulationController* simulation, QMainWindow* window)
    : QObject(window), document_(document), view_(view), simulation_(simulation), window_(window) {}

QMessageBox* WatchAlert::dialog() const {
  return dialog_;
}

void WatchAlert::showSnapshot(const SimulationSnapshot& snapshot, bool following) {
  if (snapshot.watchEvents == eventsShown_) return;
  eventsShown_ = snapshot.watchEvents;
  if (snapshot.watchEvent) show(snapshot, following);
}

void WatchAlert::show(const SimulationSnapshot& snapshot, bool following) {
  const WatchEvent& event = *snapshot.watchEvent;
  const Scene& scene = document_->scene();
  const QString text = watchEventText(event, scene);
  // Stays until another message replaces it: the dialog may be closed before it is read.
  window_->statusBar()->showMessage(tr("Stopped by the watch: %1").arg(text));
  if (event.ball >= 0 && event.ball < int(scene.balls.size())) {
    document_->setSelection({{editor::ObjectKind::Ball, event.ball}});
    // Following a ball, the view now follows this one (the selection's); otherwise it frames it.
    const bool known =
        event.ball < int(snapshot.positions.size()) && snapshot.positions[event.ball].allFinite();
    if (known && !following) {
      const Vec3 reach = Vec3::Constant(kFrameRadii * scene.balls[event.ball].radius);
      const Vec3& centre = snapshot.positions[event.ball];
      view_->camera().frame({centre - reach, centre + reach});
      view_->update();
    }
  }
  // Shown without waiting: snapshots keep coming while it is up. A newer event replaces it.
  if (dialog_) dialog_->close();
  auto* box = new QMessageBox(QMessageBox::Warning, tr("Simulation Stopped"), text, QMessageBox::Ok,
                              window_);
  box->setObjectName("watchDialog");
  box->setInformativeText(
      tr("The run is paused. The last step that passed the watch ended at %1 s. The checks "
         "and their tolerances are in Simulation > Watch.")
          .arg(editor::formatShortNumber(event.lastGoodTime)));
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->setWindowModality(Qt::WindowModal);
  // The timeline holds the frame before the event: the last one that passed.
  if (snapshot.frameCount > 0) {
    QPushButton* before = box->addButton(tr("Show the Moment Before"), QMessageBox::ActionRole);
    before->setObjectName("showMomentBefore");
    const std::uint64_t frame = snapshot.frameCount - 1;
    connect(before, &QPushButton::clicked, this, [this, frame] { simulation_->showFrame(frame); });
  }
  dialog_ = box;
  box->show();
  emit stopped(event);
}

}  // namespace carom::ui
