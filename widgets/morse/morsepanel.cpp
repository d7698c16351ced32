#include "morsepanel.h"

#include "morselivesource.h"
#include "widgets/common/plot.h"

#include <QComboBox>
#include <QDateTime>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QPainter>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSplitter>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace db::widgets {
namespace {

constexpr int kFrameWidth = 320; // px, the frame preview
constexpr double kTimelineBand = 0.12; // the dit/dah band: lowest 12 % of the plot
constexpr double kThresholdStep = 0.25; // s of samples per decoder feed and threshold point

QString confidenceText(const morse::IpEstimate &ip)
{
    return QStringLiteral("%1 %").arg(ip.confidence * 100.0, 0, 'f', 0);
}

} // namespace

MorsePanel::MorsePanel(QWidget *parent)
    : QWidget(parent)
    , m_decoder(std::make_unique<morse::Decoder>())
    , m_timer(new QTimer(this))
    , m_open(new QPushButton(tr("Open video or CSV…"), this))
    , m_cameras(new QComboBox(this))
    , m_startCamera(new QPushButton(tr("Start camera"), this))
    , m_stopCamera(new QPushButton(tr("Stop"), this))
    , m_liveRefresh(new QTimer(this))
    , m_sourceLabel(new QLabel(tr("No recording"), this))
    , m_frame(new QLabel(this))
    , m_plot(new QCustomPlot(this))
    , m_text(new QPlainTextEdit(this))
    , m_ip(new QLabel(this))
    , m_status(new QLabel(this))
    , m_connect(new QToolButton(this))
{
    setObjectName(QStringLiteral("MorsePanel"));
    m_frame->setObjectName(QStringLiteral("morseFrame"));
    m_sourceLabel->setObjectName(QStringLiteral("morseSource"));
    m_frame->setMinimumSize(kFrameWidth * 3 / 4, 135);
    m_frame->setAlignment(Qt::AlignCenter);
    m_frame->setText(tr("LED frame"));
    m_frame->setFrameShape(QFrame::StyledPanel);
    m_text->setReadOnly(true);
    m_text->setMaximumBlockCount(50);
    m_text->setObjectName(QStringLiteral("morseText"));
    m_ip->setObjectName(QStringLiteral("morseIp"));
    QFont big = m_ip->font();
    big.setPointSizeF(big.pointSizeF() * 1.6);
    big.setBold(true);
    m_ip->setFont(big);
    m_ip->setText(tr("IP: –"));
    m_status->setWordWrap(true);

    m_connect->setText(tr("Connect"));
    m_connect->setObjectName(QStringLiteral("morseConnect"));
    m_connect->setPopupMode(QToolButton::MenuButtonPopup);
    m_connect->setEnabled(false);
    auto *menu = new QMenu(m_connect);
    QAction *refgo = menu->addAction(tr("MovingCap RefGo (refgo://IP)"));
    QAction *slcan = menu->addAction(tr("CANopen over SLCAN (canopen+slcan://IP?node=50)"));
    m_connect->setMenu(menu);
    connect(m_connect, &QToolButton::clicked, this,
            [this] { Q_EMIT connectRequested(QStringLiteral("refgo://%1").arg(ipText())); });
    connect(refgo, &QAction::triggered, m_connect, &QToolButton::click);
    connect(slcan, &QAction::triggered, this, [this] {
        Q_EMIT connectRequested(QStringLiteral("canopen+slcan://%1?node=50").arg(ipText()));
    });

    m_plot->setMinimumSize(300, 150);
    m_plot->xAxis->setLabel(tr("time (s)"));
    m_plot->yAxis->setLabel(tr("brightness"));
    m_brightness = m_plot->addGraph();
    m_brightness->setPen(QPen(QColor(40, 110, 200), 1.2));
    m_brightness->setName(tr("brightness"));
    m_threshold = m_plot->addGraph();
    m_threshold->setPen(QPen(QColor(220, 120, 0), 1.5, Qt::DashLine));
    m_threshold->setName(tr("threshold"));
    m_dits = m_plot->addGraph(m_plot->xAxis, m_plot->yAxis2);
    m_dits->setPen(Qt::NoPen);
    m_dits->setBrush(QColor(40, 160, 60));
    m_dits->setLineStyle(QCPGraph::lsStepLeft);
    m_dits->setName(tr("dit"));
    m_dahs = m_plot->addGraph(m_plot->xAxis, m_plot->yAxis2);
    m_dahs->setPen(Qt::NoPen);
    m_dahs->setBrush(QColor(150, 40, 160));
    m_dahs->setLineStyle(QCPGraph::lsStepLeft);
    m_dahs->setName(tr("dah"));
    m_plot->yAxis2->setRange(0.0, 1.0 / kTimelineBand);
    m_plot->legend->setVisible(true);
    m_plot->legend->setFont(font());
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);

    auto *top = new QHBoxLayout;
    top->addWidget(m_open);
    top->addWidget(m_cameras);
    top->addWidget(m_startCamera);
    top->addWidget(m_stopCamera);
    top->addWidget(m_sourceLabel, 1);
    auto *side = new QVBoxLayout;
    side->addWidget(m_frame);
    side->addWidget(m_ip);
    side->addWidget(m_status);
    auto *connectRow = new QHBoxLayout;
    connectRow->addWidget(m_connect);
    connectRow->addStretch(1);
    side->addLayout(connectRow);
    side->addStretch(1);
    auto *right = new QVBoxLayout;
    right->addWidget(m_plot, 3);
    right->addWidget(m_text, 1);
    auto *body = new QHBoxLayout;
    body->addLayout(side);
    body->addLayout(right, 1);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addLayout(body, 1);

    connect(m_open, &QPushButton::clicked, this, &MorsePanel::chooseFile);
    m_timer->setInterval(1000 / kReplotHz);
    connect(m_timer, &QTimer::timeout, this, &MorsePanel::step);
    m_cameras->setObjectName(QStringLiteral("morseCameras"));
    m_cameras->setMinimumContentsLength(18);
    m_cameras->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_startCamera->setObjectName(QStringLiteral("morseStartCamera"));
    m_stopCamera->setObjectName(QStringLiteral("morseStopCamera"));
    connect(m_startCamera, &QPushButton::clicked, this,
            [this] { startLive(m_cameras->currentIndex()); });
    connect(m_stopCamera, &QPushButton::clicked, this, &MorsePanel::stopLive);
    m_liveRefresh->setSingleShot(true);
    m_liveRefresh->setInterval(1000 / kReplotHz);
    connect(m_liveRefresh, &QTimer::timeout, this, [this] {
        if (isVisible())
            refresh();
    });
    m_frame->installEventFilter(this);
    rebuildCameraList();
    refresh();
}

MorsePanel::~MorsePanel()
{
    // A live source that is a child dies in QWidget's destructor, after this panel's members:
    // it must not call back into them.
    if (m_liveSource)
        disconnect(m_liveSource, nullptr, this, nullptr);
}

void MorsePanel::chooseFile()
{
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open a video of the LED or a CSV of samples"), QString(),
        tr("Videos and CSV (*.mp4 *.mov *.avi *.mkv *.webm *.3gp *.csv *.txt);;All files (*)"));
    if (!path.isEmpty())
        openFile(path);
}

bool MorsePanel::openFile(const QString &path)
{
    if (!m_loader) {
        m_status->setText(tr("No file reader in this build."));
        return false;
    }
    auto loaded = m_loader(path);
    if (!loaded) {
        // The previous file's text and IP are not this file's: they go, the reason stays.
        setSource({});
        m_error = loaded.error().message();
        refresh();
        return false;
    }
    setSource(std::move(loaded).value());
    return true;
}

void MorsePanel::setSource(MorseSource source)
{
    if (m_live)
        stopLive();
    m_error.clear();
    m_timer->stop();
    m_source = std::move(source);
    m_decoder = std::make_unique<morse::Decoder>();
    m_fed = 0;
    m_thresholdT.clear();
    m_thresholdV.clear();
    m_sourceLabel->setText(m_source.description);
    m_brightness->data()->clear();
    updateFrame();
    if (!m_source.samples.empty()) {
        m_playStart = m_source.samples.front().t;
        m_wallStart = QDateTime::currentMSecsSinceEpoch();
        m_timer->start();
    }
    refresh();
}

bool MorsePanel::playing() const
{
    return m_timer->isActive();
}

void MorsePanel::finishPlayback()
{
    feedUntil(m_source.samples.size());
    m_timer->stop();
    m_decoder->finish();
    refresh();
}

void MorsePanel::step()
{
    const double now = m_playStart
        + kPlaybackSpeed * double(QDateTime::currentMSecsSinceEpoch() - m_wallStart) / 1000.0;
    std::size_t end = m_fed;
    while (end < m_source.samples.size() && m_source.samples[end].t <= now)
        ++end;
    // The decoder cuts the recording at a gap longer than kMaxSampleGap: playback skips it
    // instead of waiting for it (a gap of hours in a file).
    const auto &s = m_source.samples;
    if (end == m_fed && end > 0 && end < s.size()
        && s[end].t - s[end - 1].t > morse::kMaxSampleGap) {
        m_playStart += s[end].t - now;
        ++end;
    }
    feedUntil(end);
    if (m_fed >= m_source.samples.size()) {
        m_timer->stop();
        m_decoder->finish();
    }
    if (isVisible())
        refresh();
}

void MorsePanel::feedUntil(std::size_t end)
{
    if (end <= m_fed)
        return;
    // In pieces of at most kThresholdStep seconds, so that the threshold curve has a point per
    // piece also when the rest of a file is decoded at once (finishPlayback()).
    while (m_fed < end) {
        std::size_t to = m_fed + 1;
        const double until = m_source.samples[m_fed].t + kThresholdStep;
        while (to < end && m_source.samples[to].t < until)
            ++to;
        const std::span<const morse::Sample> chunk(m_source.samples.data() + m_fed, to - m_fed);
        m_decoder->feed(chunk);
        for (const morse::Sample &s : chunk)
            m_brightness->addData(s.t, s.value);
        if (m_decoder->slicer().found()) {
            m_thresholdT.push_back(chunk.back().t);
            m_thresholdV.push_back((m_decoder->slicer().low() + m_decoder->slicer().high()) / 2.0);
        }
        m_fed = to;
    }
}

QString MorsePanel::ipText() const
{
    return m_decoder->ip().complete() ? m_decoder->ip().toString() : QString();
}

QString MorsePanel::statusText() const
{
    return m_status->text();
}

void MorsePanel::refresh()
{
    const morse::Decoder &d = *m_decoder;
    // Threshold: one point per fed chunk, as the slicer tracked it.
    m_threshold->setData(QVector<double>(m_thresholdT.begin(), m_thresholdT.end()),
                         QVector<double>(m_thresholdV.begin(), m_thresholdV.end()), true);
    QVector<double> t;
    QVector<double> dit;
    QVector<double> dah;
    for (const morse::Element &e : d.timeline()) {
        const bool isDit = e.kind == morse::ElementKind::Dit;
        const bool isDah =
            e.kind == morse::ElementKind::Dah || e.kind == morse::ElementKind::LongMark;
        t << e.start << e.start + e.duration;
        dit << (isDit ? 0.8 : qQNaN()) << qQNaN();
        dah << (isDah ? 0.8 : qQNaN()) << qQNaN();
    }
    m_dits->setData(t, dit, true);
    m_dahs->setData(t, dah, true);
    if (!m_source.samples.empty()) {
        const double t1 = m_fed > 0 ? m_source.samples[m_fed - 1].t : m_source.samples.front().t;
        m_plot->xAxis->setRange(std::max(m_source.samples.front().t, t1 - 20.0),
                                std::max(t1, m_source.samples.front().t + 1.0));
        bool found = false;
        const QCPRange y = m_brightness->getValueRange(found);
        if (found) {
            const double pad = std::max(1e-6, y.size());
            m_plot->yAxis->setRange(y.lower - pad * kTimelineBand / (1.0 - kTimelineBand)
                                        - 0.05 * pad,
                                    y.upper + 0.1 * pad);
        }
    }
    m_plot->replot(QCustomPlot::rpQueuedReplot);

    // Messages sent back to back are one run of text without spaces: a zero-width space after
    // each ':' lets the lines break between messages rather than anywhere.
    QString text = d.text();
    text.replace(QLatin1Char(':'), QStringLiteral(":\u200B"));
    if (m_text->toPlainText() != text)
        m_text->setPlainText(text);
    const morse::IpEstimate &ip = d.ip();
    if (ip.complete() || ip.confidence > 0.0)
        m_ip->setText(tr("IP: %1  (%2)").arg(ip.toString(), confidenceText(ip)));
    else if (ip.anyOctet())
        m_ip->setText(tr("IP: %1  (partly read)").arg(ip.toString()));
    else
        m_ip->setText(tr("IP: –"));
    m_connect->setEnabled(ip.complete());
    QString status;
    if (!m_error.isEmpty())
        status = m_error;
    else if (m_source.samples.empty() && m_live)
        status = tr("Waiting for the blinking LED…");
    else if (m_source.samples.empty())
        status = tr("Open a video of the green STATUS LED (at least two message repetitions) or a "
                    "CSV of samples, or start a camera.");
    else if (d.confident())
        status = tr("Confident: %1 agreeing messages, unit %2 ms")
                     .arg(ip.messages)
                     .arg(d.unitFit().unit * 1000.0, 0, 'f', 0)
            + (d.gapCount() > 0 ? QStringLiteral("; ") + d.gapNote() : QString())
            + QLatin1Char('.');
    else
        status = (playing() || m_live ? tr("Decoding… ") : QString()) + d.reasonMessage();
    m_status->setText(status);
}

void MorsePanel::updateFrame()
{
    if (m_source.frame.isNull()) {
        m_frame->setPixmap({});
        m_frame->setText(m_source.samples.empty() ? tr("LED frame") : tr("(CSV: no frame)"));
        return;
    }
    QImage img = m_source.frame.scaledToWidth(kFrameWidth, Qt::SmoothTransformation)
                     .convertToFormat(QImage::Format_RGB32);
    if (!m_source.region.isEmpty()) {
        // The region is in the source frame's pixels; the preview may be smaller.
        const double s = double(img.width()) / double(std::max(1, m_source.frameWidth));
        QPainter p(&img);
        p.setPen(QPen(QColor(255, 60, 60), 2));
        const QRectF r(m_source.region.x() * s, m_source.region.y() * s,
                       m_source.region.width() * s, m_source.region.height() * s);
        p.drawRect(r.adjusted(-2, -2, 2, 2));
    }
    m_frame->setPixmap(QPixmap::fromImage(img));
}

} // namespace db::widgets
