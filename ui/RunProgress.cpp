// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/RunProgress.h"

#include <QLocale>

#include <cmath>

namespace kinstab::ui {

RunProgress::RunProgress(QWidget* parent) : QProgressBar(parent) {
    setTextVisible(true);
    setRange(0, 1000);
    // One line of text at the status bar's font: about 48 characters.
    setMinimumWidth(fontMetrics().horizontalAdvance(QLatin1Char('0')) * 48);
    hide();
}

QString timeLeftText(double seconds) {
    const long s = std::lround(seconds);
    if (s < 60) return RunProgress::tr("about %1 s left").arg(std::max(s, 1L));
    const long min = std::lround(seconds / 60.0);
    if (min < 60) return RunProgress::tr("about %1 min left").arg(min);
    return RunProgress::tr("about %1 h %2 min left").arg(min / 60).arg(min % 60);
}

void RunProgress::start(qint64 total, const QString& unit) {
    m_unit = unit;
    m_left.reset();
    m_clock.start();
    setValue(0);
    setFormat(total > 0 ? tr("0 / %1 %2").arg(QLocale().toString(total), unit) : tr("starting…"));
    show();
}

void RunProgress::update(qint64 done, qint64 total) {
    if (total <= 0) return;
    m_left.update(m_clock.elapsed() / 1000.0, static_cast<std::size_t>(done),
                  static_cast<std::size_t>(total));
    setValue(static_cast<int>(1000 * done / total));
    QString text =
        tr("%1 / %2 %3").arg(QLocale().toString(done), QLocale().toString(total), m_unit);
    if (m_left.rate() > 0)
        text +=
            tr(" · %1 /s").arg(QLocale().toString(m_left.rate(), 'f', m_left.rate() < 10 ? 1 : 0));
    if (const auto left = m_left.secondsLeft(); left && done < total)
        text += QStringLiteral(" · ") + timeLeftText(*left);
    setFormat(text);
}

void RunProgress::finish() {
    hide();
    setFormat(QString());
}

} // namespace kinstab::ui
