#include "lsspanel.h"

#include "canopen/cannetwork.h"
#include "canopen/lssmaster.h"
#include "core/changelog.h"
#include "core/reply.h"
#include "widgets/common/flowlayout.h"
#include "widgets/common/widgetstyle.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTime>
#include <QVBoxLayout>

namespace db::widgets {

using canopen::LssAddress;
using canopen::LssMode;
namespace lss = canopen::lss;

LssPanel::LssPanel(QWidget *parent)
    : QWidget(parent)
    , m_nodeId(new QSpinBox(this))
    , m_bitrate(new QComboBox(this))
    , m_log(new QPlainTextEdit(this))
{
    const auto button = [this](const char *name, const QString &text, const QString &toolTip,
                               auto slot) {
        auto *b = new QPushButton(text, this);
        b->setObjectName(QString::fromLatin1(name));
        b->setToolTip(toolTip);
        connect(b, &QPushButton::clicked, this, slot);
        m_buttons.append(b);
        return b;
    };
    QPushButton *configuration =
        button("lssConfiguration", tr("All: configuration"),
               tr("Every LSS slave to configuration mode (use it when only one is on the bus)"),
               [this] { switchAll(true); });
    QPushButton *waiting = button("lssWaiting", tr("All: waiting"),
                                  tr("Every LSS slave back to waiting (normal operation)"),
                                  [this] { switchAll(false); });
    QPushButton *fastscanButton =
        button("lssFastscan", tr("Fastscan"),
               tr("Find one slave without a node id; it stays in configuration mode"),
               [this] { fastscan(); });
    QPushButton *inquireButton =
        button("lssInquire", tr("Inquire identity"),
               tr("Vendor, product, revision, serial and node id of the slave in configuration "
                  "mode"),
               [this] { inquire(); });
    QPushButton *assignNode =
        button("lssAssignNode", tr("Assign node id"),
               tr("Give the slave in configuration mode this node id (applied at its next reset "
                  "communication; Store keeps it)"),
               [this] { assignNodeId(m_nodeId->value()); });
    QPushButton *assignRate =
        button("lssAssignBitrate", tr("Assign bit rate"),
               tr("Give the slave in configuration mode this bit rate (Store keeps it; it applies "
                  "after a restart)"),
               [this] { assignBitrate(m_bitrate->currentData().toInt()); });
    QPushButton *storeButton = button(
        "lssStore", tr("Store"),
        tr("The slave in configuration mode keeps its node id and bit rate"), [this] { store(); });

    m_nodeId->setObjectName(QStringLiteral("lssNodeId"));
    m_nodeId->setRange(1, 127);
    m_bitrate->setObjectName(QStringLiteral("lssBitrate"));
    for (int i = 0; i <= 8; ++i) {
        if (const int rate = lss::bitrateOfIndex(i); rate > 0)
            m_bitrate->addItem(tr("%1 kbit/s").arg(rate / 1000), rate);
    }
    m_log->setObjectName(QStringLiteral("lssLog"));
    m_log->setReadOnly(true);
    m_log->setFont(style::monospaceFont());
    m_log->setMaximumBlockCount(500);

    auto *modes = new FlowLayout;
    modes->setContentsMargins(0, 0, 0, 0);
    for (QPushButton *b : { configuration, waiting, fastscanButton, inquireButton })
        modes->addWidget(b);
    auto *assign = new FlowLayout;
    assign->setContentsMargins(0, 0, 0, 0);
    assign->addWidget(new QLabel(tr("Node id:"), this));
    assign->addWidget(m_nodeId);
    assign->addWidget(assignNode);
    assign->addWidget(new QLabel(tr("Bit rate:"), this));
    assign->addWidget(m_bitrate);
    assign->addWidget(assignRate);
    assign->addWidget(storeButton);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(modes);
    layout->addLayout(assign);
    layout->addWidget(m_log, 1);
    setBusy(false);
}

LssPanel::~LssPanel() = default;

void LssPanel::setChangeLog(ChangeLog *log)
{
    m_changeLog = log;
}

void LssPanel::setNetwork(canopen::CanNetwork *network)
{
    m_network = network;
    setBusy(false);
}

QString LssPanel::logText() const
{
    return m_log->toPlainText();
}

bool LssPanel::ready()
{
    if (m_busy)
        return false;
    if (!m_network || !m_network->isOpen()) {
        log(tr("the bus is not open"), true);
        return false;
    }
    return true;
}

bool LssPanel::switchAll(bool configuration)
{
    if (!ready())
        return false;
    if (!m_network->lss()->switchModeGlobal(configuration ? LssMode::Configuration
                                                          : LssMode::Waiting)) {
        log(tr("switch mode not sent"), true);
        return false;
    }
    log(configuration ? tr("all slaves: configuration mode") : tr("all slaves: waiting"));
    return true;
}

bool LssPanel::fastscan()
{
    if (!ready())
        return false;
    log(tr("fastscan…"));
    run(m_network->lss()->fastscan(), tr("fastscan"), [this](const QVariant &value) {
        log(tr("found %1 (now in configuration mode)").arg(value.value<LssAddress>().toString()));
    });
    return true;
}

bool LssPanel::inquire()
{
    if (!ready())
        return false;
    setBusy(true);
    inquireNext(lss::InquireVendor, {});
    return true;
}

void LssPanel::inquireNext(int cs, QStringList found)
{
    if (cs > lss::InquireNodeId) {
        log(found.join(QStringLiteral(", ")));
        setBusy(false);
        Q_EMIT done(true);
        return;
    }
    Reply *reply = m_network ? m_network->lss()->inquire(quint8(cs)) : nullptr;
    if (!reply) {
        setBusy(false);
        Q_EMIT done(false);
        return;
    }
    connect(reply, &Reply::finished, this, [this, reply, cs, found]() mutable {
        reply->deleteLater();
        if (!reply->ok()) {
            log(tr("inquire: %1 (is one slave in configuration mode?)")
                    .arg(reply->error().message()),
                true);
            setBusy(false);
            Q_EMIT done(false);
            return;
        }
        static const char *const kNames[] = { QT_TR_NOOP("vendor"), QT_TR_NOOP("product"),
                                              QT_TR_NOOP("revision"), QT_TR_NOOP("serial"),
                                              QT_TR_NOOP("node id") };
        const quint32 n = quint32(reply->value().toULongLong());
        found.append(tr("%1 %2").arg(tr(kNames[cs - lss::InquireVendor]),
                                     cs == lss::InquireNodeId
                                         ? QString::number(n)
                                         : QStringLiteral("%1h").arg(n, 8, 16, QLatin1Char('0'))));
        inquireNext(cs + 1, found);
    });
}

bool LssPanel::assignNodeId(int node)
{
    if (node < 1 || node > 127 || !ready())
        return false;
    Reply *reply = m_network->lss()->configureNodeId(canopen::NodeId(node));
    record(reply, false, tr("LSS node id"), QString::number(node));
    run(reply, tr("assign node id %1").arg(node));
    return true;
}

bool LssPanel::assignBitrate(int bitrate)
{
    const int index = lss::bitTimingIndex(bitrate);
    if (index < 0 || !ready())
        return false;
    Reply *reply = m_network->lss()->configureBitTiming(quint8(index));
    record(reply, false, tr("LSS bit rate"), tr("%1 kbit/s").arg(bitrate / 1000));
    run(reply, tr("assign %1 kbit/s").arg(bitrate / 1000));
    return true;
}

bool LssPanel::store()
{
    if (!ready())
        return false;
    Reply *reply = m_network->lss()->storeConfiguration();
    record(reply, true, tr("LSS node id and bit rate"), QString());
    run(reply, tr("store"));
    return true;
}

void LssPanel::run(Reply *reply, const QString &what, std::function<void(const QVariant &)> then)
{
    setBusy(true);
    connect(reply, &Reply::finished, this, [this, reply, what, then] {
        reply->deleteLater();
        setBusy(false);
        if (!reply->ok()) {
            log(tr("%1: %2").arg(what, reply->error().message()), true);
            Q_EMIT done(false);
            return;
        }
        if (then)
            then(reply->value());
        else
            log(tr("%1: done").arg(what));
        Q_EMIT done(true);
    });
}

void LssPanel::record(Reply *reply, bool store, const QString &object, const QString &value)
{
    if (!m_changeLog || !m_network)
        return;
    ChangeLog::Entry e;
    e.device = m_network->name();
    e.kind = store ? ChangeLog::Kind::Store : ChangeLog::Kind::Write;
    e.object = object;
    e.newValue = value;
    m_changeLog->track(e, reply);
}

void LssPanel::log(const QString &text, bool error)
{
    const QString line = QTime::currentTime().toString(QStringLiteral("HH:mm:ss ")) + text;
    if (error)
        m_log->appendHtml(QStringLiteral("<span style=\"color:%1\">%2</span>")
                              .arg(style::errorColor().name(), line.toHtmlEscaped()));
    else
        m_log->appendPlainText(line);
}

void LssPanel::setBusy(bool busy)
{
    m_busy = busy;
    for (QPushButton *b : std::as_const(m_buttons))
        b->setEnabled(!busy && m_network);
}

} // namespace db::widgets
