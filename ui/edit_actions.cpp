#include "ui/edit_actions.h"

#include "sim/io/scene_file.h"
#include "ui/editor/object_ref.h"
#include "ui/editor/scene_document.h"

#include <QApplication>
#include <QClipboard>
#include <QMimeData>

#include <algorithm>

namespace carom::ui {

EditActions::EditActions(editor::SceneDocument* document, std::function<Vec3()> across,
                         QObject* parent)
    : QObject(parent), document_(document), across_(std::move(across)) {}

void EditActions::copy() {
  const editor::Selection& selection = document_->selection();
  if (selection.empty()) return;
  const QByteArray json = io::serializeScene(extract(document_->scene(), selection));
  auto* mime = new QMimeData;
  mime->setData(kSceneMimeType, json);
  mime->setText(QString::fromUtf8(json));
  QApplication::clipboard()->setMimeData(mime);
}

void EditActions::paste() {
  const QMimeData* mime = QApplication::clipboard()->mimeData();
  if (!mime) return;
  const QByteArray json =
      mime->hasFormat(kSceneMimeType) ? mime->data(kSceneMimeType) : mime->text().toUtf8();
  const io::SceneLoadResult parsed = io::parseScene(json, tr("clipboard"));
  if (!parsed.scene) {
    emit message(tr("Nothing to paste: %1").arg(parsed.error));
    return;
  }
  insertObjects(*parsed.scene, tr("Paste"));
}

void EditActions::duplicate() {
  insertObjects(extract(document_->scene(), document_->selection()), tr("Duplicate"));
}

void EditActions::deleteSelection() {
  const QString error = document_->removeObjects(document_->selection(), tr("Delete"));
  if (!error.isEmpty()) emit message(error);
}

void EditActions::selectAll() {
  const Scene& scene = document_->scene();
  editor::Selection all;
  for (editor::ObjectKind kind : editor::kObjectKinds)
    for (int i = 0; i < editor::objectCount(scene, kind); ++i) all.push_back({kind, i});
  document_->setSelection(all);
}

void EditActions::insertObjects(Scene objects, const QString& text) {
  if (objects.balls.empty() && objects.planes.empty() && objects.cylinders.empty() &&
      objects.boxes.empty())
    return;
  // Balls copied onto themselves would overlap, and a box may land on a ball: shift the balls
  // and boxes sideways together, in steps of the largest of them, until they fit.
  Vec3 across = across_ ? across_() : Vec3::UnitX();
  if (!across.allFinite() || across.norm() < 0.5) across = Vec3::UnitX();
  double largest = 0.0;
  for (const Ball& ball : objects.balls) largest = std::max(largest, ball.radius);
  for (const Box& box : objects.boxes) largest = std::max(largest, box.halfExtents.norm());
  QString error;
  for (int attempt = 0; attempt <= kMaxPlacementAttempts; ++attempt) {
    Scene shifted = objects;
    const Vec3 offset = attempt * 2.2 * largest * across;
    for (Ball& ball : shifted.balls) ball.position += offset;
    for (Box& box : shifted.boxes) box.center += offset;
    error = document_->addObjects(shifted, text);
    if (error.isEmpty()) return;
    // Planes and cylinders never overlap anything.
    if (objects.balls.empty() && objects.boxes.empty()) break;
  }
  emit message(tr("Cannot place the objects: %1").arg(error));
}

}  // namespace carom::ui
