// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/AboutBox.h"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <QDialogButtonBox>
#include <QLabel>
#include <QLibraryInfo>
#include <QPixmap>
#include <QVBoxLayout>

namespace kinstab::ui {

namespace {
QString libraries() {
    const QString qt = QLibraryInfo::version().toString();
    return QStringLiteral("<ul>"
                          "<li>Qt %1 (Widgets, Charts, Data Visualization, PrintSupport, Svg), "
                          "built with %2 — GPL-3.0 / LGPL-3.0</li>"
                          "<li>Eigen %3.%4.%5 — MPL-2.0</li>"
                          "<li>nlohmann/json %6.%7.%8 — MIT</li>"
                          "<li>Compiler: %9</li></ul>")
        .arg(qt, QStringLiteral(QT_VERSION_STR))
        .arg(EIGEN_WORLD_VERSION)
        .arg(EIGEN_MAJOR_VERSION)
        .arg(EIGEN_MINOR_VERSION)
        .arg(NLOHMANN_JSON_VERSION_MAJOR)
        .arg(NLOHMANN_JSON_VERSION_MINOR)
        .arg(NLOHMANN_JSON_VERSION_PATCH)
        .arg(QStringLiteral("GCC " __VERSION__).toHtmlEscaped());
}
} // namespace

QString aboutHtml() {
    return QStringLiteral(
               "<h2>kinstab %1</h2>"
               "<p>Kinetic stability of friction-held slabs in earthquakes: does a slab that "
               "rests on its walls slide off before the building's members are overstressed?</p>"
               "<p><b>Licence:</b> GNU General Public License, version 3 or (at your option) any "
               "later version (GPL-3.0-or-later). kinstab comes with ABSOLUTELY NO WARRANTY. "
               "It links Qt Charts and Qt Data Visualization, which are offered under the GPL-3.0, "
               "so kinstab is GPL-3.0-or-later too.</p>"
               "<p><b>How to cite:</b> kinstab %1 (software), and the method's source: "
               "R. L. Furgerson, <i>Seismic Stability of Block Structures</i>, University of "
               "California, San Diego, report AMES TR-80/002, 1980. CITATION.cff in the "
               "source holds both.</p>"
               "<p><b>Libraries:</b></p>%2")
        .arg(QStringLiteral(KINSTAB_VERSION), libraries());
}

AboutBox::AboutBox(QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("About kinstab"));
    setObjectName(QStringLiteral("aboutBox"));
    auto* icon = new QLabel;
    icon->setPixmap(QPixmap(QStringLiteral(":/icons/kinstab.svg"))
                        .scaled(64, 64, Qt::KeepAspectRatio, Qt::SmoothTransformation));
    auto* text = new QLabel(aboutHtml());
    text->setObjectName(QStringLiteral("aboutText"));
    text->setWordWrap(true);
    text->setTextFormat(Qt::RichText);
    text->setTextInteractionFlags(Qt::TextBrowserInteraction);
    text->setMinimumWidth(520);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(icon, 0, Qt::AlignHCenter);
    layout->addWidget(text);
    layout->addWidget(buttons);
}

} // namespace kinstab::ui
