// SPDX-License-Identifier: GPL-3.0-or-later
// TeachingView, continued: Save frame (PNG, SVG) and Save run as PNGs, and the calls tests and
// scripts make for the same files.

#include "ui/ProjectFolder.h"
#include "ui/teaching/FrameExport.h"
#include "ui/teaching/TeachingPlayer.h"
#include "ui/teaching/TeachingView.h"

#include <QFileDialog>
#include <QMessageBox>
#include <QProgressDialog>

namespace kinstab::ui {

QString TeachingView::exportFramePng(const QString& path, QSize size) const {
    return saveFramePng(path, *run_, player_->tau(), size, units_);
}

QString TeachingView::exportFrameSvg(const QString& path, QSize size) const {
    return saveFrameSvg(path, *run_, player_->tau(), size, units_);
}

int TeachingView::exportSequence(const QString& directory, double framesPerSecond, QSize size,
                                 QString* error) {
    SequenceOptions o;
    o.framesPerSecond = framesPerSecond;
    o.speed = player_->speed();
    o.size = size;
    o.units = units_;
    const SequenceResult r = saveFrameSequence(directory, *run_, o);
    if (error) *error = r.error;
    return r.error.isEmpty() ? r.frames : 0;
}

void TeachingView::exportFrameDialog() {
    QString filter;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save frame"), inOpenProjectFolder("teaching-frame.png"),
        tr("PNG image (*.png);;SVG drawing (*.svg)"), &filter);
    if (path.isEmpty()) return;
    const bool svg = path.endsWith(QStringLiteral(".svg"), Qt::CaseInsensitive) ||
                     filter.contains(QStringLiteral("svg"));
    const QString err = svg ? exportFrameSvg(path) : exportFramePng(path);
    if (!err.isEmpty()) QMessageBox::warning(this, tr("Save frame"), err);
}

void TeachingView::exportSequenceDialog() {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Folder for the PNG sequence"));
    if (dir.isEmpty()) return;
    player_->pause();
    QProgressDialog progress(tr("Writing frames…"), tr("Cancel"), 0, 100, this);
    progress.setWindowModality(Qt::WindowModal);
    SequenceOptions o;
    o.speed = player_->speed();
    o.units = units_;
    const SequenceResult r = saveFrameSequence(dir, *run_, o, [&](int done, int total) {
        progress.setMaximum(total);
        progress.setValue(done);
        return !progress.wasCanceled();
    });
    if (!r.error.isEmpty()) QMessageBox::warning(this, tr("Save run"), r.error);
}

} // namespace kinstab::ui
