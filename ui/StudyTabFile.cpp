// SPDX-License-Identifier: GPL-3.0-or-later
// StudyTab, continued: the study file and the fields - the file text the fields describe, and
// the fields filled from a study file opened.

#include "core/base/TextInput.h"
#include "core/io/StudyFileWriter.h"
#include "core/io/StudySpecJson.h"
#include "ui/StudyTab.h"

#include <nlohmann/json.hpp>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>

#include <algorithm>
#include <set>

namespace kinstab::ui {

namespace {

std::vector<std::string> patternList(const QString& text) {
    std::vector<std::string> a;
    for (const QString& p : text.split(',', Qt::SkipEmptyParts))
        a.push_back(p.trimmed().toStdString());
    return a;
}

QString joined(const std::vector<double>& values) {
    QStringList out;
    for (double v : values)
        out << QString::fromStdString(formatDouble(v));
    return out.join(", ");
}

// A LIST field's text with its items trimmed and joined by ", ": "0.4,0.6" and "0.4, 0.6" are
// one list, and must not mark results stale.
std::string listText(const QLineEdit* field) {
    QStringList items;
    for (const QString& item : field->text().split(',', Qt::SkipEmptyParts))
        items << item.trimmed();
    return items.join(", ").toStdString();
}

// The floor periods of the study's floor filters, each once ("" when the ground drives all).
QString floorPeriods(const StudySpec& s) {
    std::vector<double> periods;
    for (const auto& f : s.floors)
        if (f && std::find(periods.begin(), periods.end(), f->period) == periods.end())
            periods.push_back(f->period);
    return joined(periods);
}

} // namespace

// A block study (its "block" instead of the slab) has no μ or t*: the fields say so and stay
// out of the file (core/io/StudyFileWriter keeps the block).
void StudyTab::showBlockStudy(bool block) {
    for (QLineEdit* e : {m_mu, m_tstar}) {
        e->setEnabled(!block);
        if (block) e->clear();
        e->setPlaceholderText(block ? tr("a block study: the study file's \"block\" sets it")
                                    : QString());
    }
}

std::string StudyTab::studyJson() const {
    StudyFileFields f;
    f.folder = m_folder->text().toStdString();
    f.include = patternList(m_include->text());
    f.exclude = patternList(m_exclude->text());
    const QStringList fields{m_folder->text(), m_include->text(), m_exclude->text()};
    if (fields == m_openedRecordFields) f.openedRecords = m_openedRecords;
    f.measure = m_measure->currentText().toStdString();
    f.saPeriodS = m_saPeriod->value();
    // LIST text ("0.4,0.6" or "0.3:0.8:0.1") is what the study file's lists accept too.
    f.mu = listText(m_mu);
    f.tstar = listText(m_tstar);
    if (!m_floors->text().trimmed().isEmpty()) f.floorPeriods = listText(m_floors);
    f.maxG = m_maxG->value();
    f.scanStepG = m_step->value();
    return studyFileText(m_base, f);
}

bool StudyTab::openStudy(const QString& path) {
    StudySpec spec;
    nlohmann::json j;
    try {
        spec = loadStudy(path.toStdString());
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly)) throw StudyError(f.errorString().toStdString());
        j = nlohmann::json::parse(f.readAll().toStdString()); // loadStudy has validated it
    } catch (const std::exception& e) {
        m_status->setText(tr("Cannot open the study %1: %2").arg(path, e.what()));
        return false;
    }
    std::set<QString> folders;
    QStringList names;
    for (const StudyRecord& r : spec.records) {
        folders.insert(QFileInfo(QString::fromStdString(r.file)).absolutePath());
        names << QFileInfo(QString::fromStdString(r.file)).fileName();
    }
    if (folders.size() != 1) {
        m_status->setText(tr("Cannot open the study %1: its records lie in %2 folders; this tab "
                             "shows one folder (run it with kinstab-cli study)")
                              .arg(path)
                              .arg(folders.size()));
        return false;
    }
    m_base = j;
    setRecordsFolder(*folders.begin(), names.join(", "), QString());
    m_openedRecords = nlohmann::json::array();
    for (const StudyRecord& r : spec.records)
        m_openedRecords.push_back({{"path", r.file}});
    m_openedRecordFields = {m_folder->text(), m_include->text(), m_exclude->text()};
    const bool sa = spec.intensity.kind == IntensityMeasure::Kind::Sa;
    m_measure->setCurrentText(sa ? "sa" : "pga");
    if (sa) m_saPeriod->setValue(spec.intensity.period);
    setLists(joined(spec.mu), joined(spec.tstar), floorPeriods(spec));
    showBlockStudy(spec.block.has_value());
    setSearch(spec.search.to, spec.search.scanStep);
    m_studyFile = path;
    m_openedText = studyJson();
    m_status->setText(tr("Opened %1: %2 records.").arg(path).arg(spec.records.size()));
    return true;
}

} // namespace kinstab::ui
