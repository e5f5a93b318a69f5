// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/TransportBar.h"

#include "ui/teaching/TeachingPlayer.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QShortcut>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace kinstab::ui {

namespace {
const double kSpeeds[] = {0.1, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0};
} // namespace

TransportBar::TransportBar(TeachingPlayer* player, std::function<double()> end, const Texts& texts,
                           QWidget* parent)
    : QWidget(parent), player_(player), end_(std::move(end)) {
    auto* h = new QHBoxLayout(this);
    h->setContentsMargins(0, 0, 0, 0);
    buildButtons(texts);
    scrub_ = new QSlider(Qt::Horizontal, this);
    scrub_->setRange(0, kScrubSteps);
    scrub_->setToolTip(tr("Scrub through the run"));
    connect(scrub_, &QSlider::valueChanged, this,
            [this](int v) { player_->seek(end_() * v / kScrubSteps); });
    h->addWidget(scrub_, 1);
    timeLabel_ = new QLabel(this);
    timeLabel_->setMinimumWidth(texts.timeWidth);
    h->addWidget(timeLabel_);
    buildSpeed(texts);
}

void TransportBar::buildButtons(const Texts& texts) {
    auto* h = layout();
    auto tool = [&](QStyle::StandardPixmap icon, const QString& tip, auto slot) {
        auto* b = new QToolButton(this);
        b->setIcon(style()->standardIcon(icon));
        b->setToolTip(tip);
        b->setMinimumWidth(34);
        connect(b, &QToolButton::clicked, player_, slot);
        h->addWidget(b);
        return b;
    };
    tool(QStyle::SP_MediaSkipBackward, tr("Back to the start"), &TeachingPlayer::rewind);
    tool(QStyle::SP_MediaSeekBackward, tr("Previous event (B)"),
         &TeachingPlayer::stepToPreviousEvent);
    playButton_ =
        tool(QStyle::SP_MediaPlay, tr("Play / pause (space)"), &TeachingPlayer::togglePlay);
    tool(QStyle::SP_MediaSeekForward, texts.nextEventTip, &TeachingPlayer::stepToNextEvent);
    connect(player_, &TeachingPlayer::playingChanged, this, [this](bool on) {
        playButton_->setIcon(
            style()->standardIcon(on ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    });
}

void TransportBar::buildSpeed(const Texts& texts) {
    speed_ = new QComboBox(this);
    for (double s : kSpeeds)
        speed_->addItem(QStringLiteral("%1×").arg(s), s);
    speed_->setCurrentIndex(static_cast<int>(
        std::find(std::begin(kSpeeds), std::end(kSpeeds), TeachingPlayer::kDefaultSpeed) -
        std::begin(kSpeeds)));
    speed_->setToolTip(texts.speedTip);
    connect(speed_, &QComboBox::currentIndexChanged, this,
            [this](int i) { player_->setSpeed(speed_->itemData(i).toDouble()); });
    // The player's speed set elsewhere (a preset, presentation mode): the nearest choice shows.
    connect(player_, &TeachingPlayer::speedChanged, this, [this](double s) {
        const QSignalBlocker block(speed_);
        int best = 0;
        for (int i = 0; i < speed_->count(); ++i)
            if (std::abs(speed_->itemData(i).toDouble() - s) <
                std::abs(speed_->itemData(best).toDouble() - s))
                best = i;
        speed_->setCurrentIndex(best);
    });
    layout()->addWidget(speed_);
}

void TransportBar::installKeys(QWidget* view) {
    auto key = [&](QKeyCombination k, auto slot) {
        auto* s =
            new QShortcut(QKeySequence(k), view, nullptr, nullptr, Qt::WidgetWithChildrenShortcut);
        connect(s, &QShortcut::activated, player_, slot);
    };
    key(Qt::Key_Space, &TeachingPlayer::togglePlay);
    key(Qt::Key_N, &TeachingPlayer::stepToNextEvent);
    key(Qt::Key_B, &TeachingPlayer::stepToPreviousEvent);
}

void TransportBar::showPosition(double at, const QString& timeText) {
    {
        const QSignalBlocker block(scrub_);
        const double end = end_();
        scrub_->setValue(end > 0 ? static_cast<int>(std::lround(at / end * kScrubSteps)) : 0);
    }
    timeLabel_->setText(timeText);
}

} // namespace kinstab::ui
