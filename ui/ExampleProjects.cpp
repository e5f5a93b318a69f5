// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/ExampleProjects.h"

#include <QDir>
#include <QFile>
#include <QMenu>
#include <QMessageBox>
#include <QStandardPaths>

namespace kinstab::ui {

const std::vector<ExampleProject>& exampleProjects() {
    static const std::vector<ExampleProject> list = {
        {QObject::tr("The paper's 16-story building (Furgerson 1980, ch. V)"),
         QStringLiteral(":/examples/paper-16-story.json"),
         {}},
        {QObject::tr("The same building under the Pacoima Dam record"),
         QStringLiteral(":/examples/paper-16-story-record.json"),
         {QStringLiteral("records/RSN77_SFERN_PUL164.AT2")}},
        {QObject::tr("The same building's floor motions under that record (16 levels)"),
         QStringLiteral(":/examples/paper-16-story-floors.json"),
         {QStringLiteral("records/RSN77_SFERN_PUL164.AT2")}},
        {QObject::tr("The same building with free-standing blocks on the roof (rocking)"),
         QStringLiteral(":/examples/paper-16-story-blocks.json"),
         {QStringLiteral("records/RSN77_SFERN_PUL164.AT2")}},
        // The study spec names ../records/*.AT2 without the vertical components: the six
        // horizontal records below, all of which must sit beside the copy or the study shrinks.
        {QObject::tr("The same building with a record-suite study (collapse fragility)"),
         QStringLiteral(":/examples/paper-16-story-study.json"),
         {QStringLiteral("examples/study-example.json"),
          QStringLiteral("records/RSN6_IMPVALL.I_I-ELC180.AT2"),
          QStringLiteral("records/RSN68_SFERN_PEL090.AT2"),
          QStringLiteral("records/RSN68_SFERN_PEL180.AT2"),
          QStringLiteral("records/RSN77_SFERN_PUL164.AT2"),
          QStringLiteral("records/Rinaldi228.AT2"), QStringLiteral("records/Rinaldi318.AT2")}},
        // The study's results and a PGA hazard curve give the annual rate of the slab falling.
        {QObject::tr("The same study against a site's hazard curve (risk checks)"),
         QStringLiteral(":/examples/paper-16-story-risk.json"),
         {QStringLiteral("examples/study-example.json"),
          QStringLiteral("examples/study-example.jsonl"),
          QStringLiteral("examples/hazard-second-order.csv"),
          QStringLiteral("records/RSN6_IMPVALL.I_I-ELC180.AT2"),
          QStringLiteral("records/RSN68_SFERN_PEL090.AT2"),
          QStringLiteral("records/RSN68_SFERN_PEL180.AT2"),
          QStringLiteral("records/RSN77_SFERN_PUL164.AT2"),
          QStringLiteral("records/Rinaldi228.AT2"), QStringLiteral("records/Rinaldi318.AT2")}},
        {QObject::tr("Planar slab, gravity only (Furgerson 1980, ch. VI)"),
         QStringLiteral(":/examples/paper-planar.json"),
         {}},
    };
    return list;
}

QString exampleRoot() {
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
}

namespace {
// Copies resource ":/REL" to root/REL, replacing an older copy; empty on success.
QString copyResource(const QString& rel, const QString& root) {
    const QString target = root + QLatin1Char('/') + rel;
    if (!QDir().mkpath(QFileInfo(target).absolutePath()))
        return QObject::tr("cannot create the folder %1").arg(QFileInfo(target).absolutePath());
    QFile::remove(target);
    QFile source(QStringLiteral(":/") + rel);
    if (!source.copy(target)) return QObject::tr("%1: %2").arg(target, source.errorString());
    QFile::setPermissions(target, QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup |
                                      QFile::ReadOther);
    return {};
}
} // namespace

QString copyExample(const ExampleProject& e, const QString& dir, QString* error) {
    const QString rel = e.resource.mid(2); // "examples/NAME.json"
    QStringList files = e.extras;
    files << rel;
    for (const QString& r : files) {
        if (const QString why = copyResource(r, dir); !why.isEmpty()) {
            if (error) *error = why;
            return {};
        }
    }
    return dir + QLatin1Char('/') + rel;
}

void addExampleMenu(QMenu* menu, const std::function<void(const QString&)>& open) {
    QMenu* examples = menu->addMenu(QObject::tr("Open e&xample"));
    examples->setObjectName(QStringLiteral("exampleMenu"));
    for (const ExampleProject& e : exampleProjects()) {
        examples->addAction(e.title, menu, [e, open, menu] {
            QString error;
            const QString path = copyExample(e, exampleRoot(), &error);
            if (path.isEmpty())
                QMessageBox::warning(menu->parentWidget(), QObject::tr("Open example"), error);
            else
                open(path);
        });
    }
}

} // namespace kinstab::ui
