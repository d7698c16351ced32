#include "pdopanel.h"

#include "canopen/cannetwork.h"
#include "canopen/pdoclient.h"
#include "core/changelog.h"
#include "core/datatype.h"
#include "core/reply.h"
#include "widgets/common/widgetstyle.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QTableWidget>
#include <QVBoxLayout>

namespace db::widgets {

using canopen::PdoConfig;
using canopen::PdoMappingEntry;

namespace {

Error invalid(const QString &text)
{
    return Error(Error::Kind::InvalidArgument, text);
}

QString hex(quint32 value, int digits)
{
    return QStringLiteral("0x")
        + QString::number(value, 16).toUpper().rightJustified(digits, QLatin1Char('0'));
}

// "0x185", "185h", "389" (decimal) -> number; nullopt when it is none.
std::optional<quint32> number(const QString &text)
{
    QString t = text.trimmed();
    bool ok = false;
    quint32 value = 0;
    if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        value = t.mid(2).toUInt(&ok, 16);
    else if (t.endsWith(QLatin1Char('h'), Qt::CaseInsensitive))
        value = t.chopped(1).toUInt(&ok, 16);
    else
        value = t.toUInt(&ok, 10);
    return ok ? std::optional<quint32>(value) : std::nullopt;
}

} // namespace

PdoPanel::PdoPanel(QWidget *parent)
    : QWidget(parent)
    , m_title(new QLabel(this))
    , m_readButton(new QPushButton(tr("Read"), this))
    , m_writeButton(new QPushButton(tr("Write"), this))
    , m_table(new QTableWidget(0, ColumnCount, this))
    , m_status(new QLabel(this))
{
    m_readButton->setObjectName(QStringLiteral("pdoRead"));
    m_writeButton->setObjectName(QStringLiteral("pdoWrite"));
    m_table->setObjectName(QStringLiteral("pdoTable"));
    m_status->setObjectName(QStringLiteral("pdoStatus"));
    m_readButton->setToolTip(tr("Read the node's PDO communication and mapping objects"));
    m_writeButton->setToolTip(
        tr("Write the changed PDOs: each is disabled, its mapping cleared, the entries written, "
           "then enabled again"));
    m_table->setHorizontalHeaderLabels({ tr("PDO"), tr("On"), tr("COB-ID"), tr("Type"),
                                         tr("Inhibit"), tr("Event"), tr("Mapping") });
    const QString headerTips[] = {
        tr("RPDO: the node receives it; TPDO: the node sends it"),
        tr("Enabled (COB-ID bit 31 clear)"),
        tr("CAN identifier (hex)"),
        tr("Transmission type: 0 acyclic synchronous, 1..240 every n-th SYNC, 254/255 event "
           "driven"),
        tr("Inhibit time in multiples of 100 µs (minimum gap between two transmissions)"),
        tr("Event timer in ms (0 = off)"),
        tr("Mapped objects as index:sub/bits, in frame order"),
    };
    for (int c = 0; c < ColumnCount; ++c)
        m_table->horizontalHeaderItem(c)->setToolTip(headerTips[c]);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setFont(style::monospaceFont());
    m_table->setSelectionBehavior(QAbstractItemView::SelectItems);
    m_table->setWordWrap(false);
    const auto chars = [this](int n) {
        return fontMetrics().horizontalAdvance(QLatin1Char('0')) * n + 16;
    };
    m_table->setColumnWidth(Pdo, chars(5));
    m_table->setColumnWidth(Enabled, chars(2));
    m_table->setColumnWidth(CobId, chars(6));
    m_table->setColumnWidth(Type, chars(4));
    m_table->setColumnWidth(Inhibit, chars(6));
    m_table->setColumnWidth(Event, chars(5));
    m_table->horizontalHeader()->setMinimumSectionSize(chars(2));
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_title, 1);
    buttons->addWidget(m_readButton);
    buttons->addWidget(m_writeButton);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(buttons);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_status);

    connect(m_readButton, &QPushButton::clicked, this, &PdoPanel::read);
    connect(m_writeButton, &QPushButton::clicked, this, &PdoPanel::write);
    connect(m_table, &QTableWidget::itemChanged, this, [this](QTableWidgetItem *item) {
        if (m_filling)
            return;
        // Changed rows are bold until they are written.
        const int row = item->row();
        auto parsed = edited();
        const bool changed = parsed && row < m_configs.size() && row < parsed->size()
            && !(parsed->at(row) == m_configs.at(row));
        m_filling = true;
        for (int c = 0; c < ColumnCount; ++c) {
            if (QTableWidgetItem *cell = m_table->item(row, c)) {
                QFont font = cell->font();
                font.setBold(changed);
                cell->setFont(font);
            }
        }
        m_filling = false;
        if (!parsed)
            showStatus(parsed.error().message(), true);
        else
            showStatus({}, false);
    });
    setNode(0);
}

PdoPanel::~PdoPanel() = default;

void PdoPanel::setChangeLog(ChangeLog *log)
{
    m_changeLog = log;
}

void PdoPanel::setNetwork(canopen::CanNetwork *network)
{
    if (network == m_network)
        return;
    delete m_client; // its SDO client belongs to the old network; open replies fail
    m_client = nullptr;
    m_network = network;
    if (network)
        m_client = new canopen::PdoClient(network->sdo(), this);
    setBusy(false);
    fill({});
    setNode(m_node);
}

void PdoPanel::setNode(canopen::NodeId node)
{
    if (node != m_node) {
        m_node = node;
        fill({});
        showStatus({}, false);
    }
    m_title->setText(node ? tr("PDOs of node %1").arg(node) : tr("Select a node"));
    setBusy(m_busy);
}

ObjectDictionary PdoPanel::dictionary() const
{
    const ObjectDictionary *d = m_network ? m_network->dictionary(m_node) : nullptr;
    return d ? *d : ObjectDictionary();
}

QString PdoPanel::mappingText(const QList<PdoMappingEntry> &entries)
{
    QStringList parts;
    for (const PdoMappingEntry &e : entries)
        parts.append(QStringLiteral("%1/%2").arg(e.address.toString()).arg(e.bits));
    return parts.join(QLatin1Char(' '));
}

Result<QList<PdoMappingEntry>> PdoPanel::parseMapping(const QString &text,
                                                      const ObjectDictionary &dictionary)
{
    QList<PdoMappingEntry> entries;
    int bits = 0;
    static const QRegularExpression separators(QStringLiteral("[\\s,;]+"));
    for (const QString &part : text.split(separators, Qt::SkipEmptyParts)) {
        const QString address = part.section(QLatin1Char('/'), 0, 0);
        auto parsed = ObjectAddress::parse(address);
        if (!parsed)
            return invalid(tr("'%1' is no object address (e.g. 6041:0/16)").arg(part));
        PdoMappingEntry entry;
        entry.address = *parsed;
        if (part.contains(QLatin1Char('/'))) {
            bool ok = false;
            const int n = part.section(QLatin1Char('/'), 1).toInt(&ok);
            if (!ok || n < 1 || n > 64)
                return invalid(tr("'%1': the length is 1..64 bits").arg(part));
            entry.bits = quint8(n);
        } else if (const ObjectDef *def = dictionary.find(*parsed);
                   def && datatype::byteSize(def->type) > 0) {
            entry.bits = quint8(datatype::byteSize(def->type) * 8);
        } else {
            return invalid(tr("'%1': give the length in bits (%2/16)").arg(part, address));
        }
        bits += entry.bits;
        entries.append(entry);
    }
    if (bits > 64)
        return invalid(tr("the mapping has %1 bits; a PDO carries at most 64").arg(bits));
    if (entries.size() > PdoConfig::kMaxEntries)
        return invalid(
            tr("%1 entries; at most %2").arg(entries.size()).arg(PdoConfig::kMaxEntries));
    return entries;
}

Result<QList<PdoConfig>> PdoPanel::edited() const
{
    QList<PdoConfig> configs;
    const ObjectDictionary dict = dictionary();
    for (int row = 0; row < m_table->rowCount() && row < m_configs.size(); ++row) {
        PdoConfig config = m_configs.at(row);
        const auto text = [&](int column) {
            const QTableWidgetItem *item = m_table->item(row, column);
            return item ? item->text().trimmed() : QString();
        };
        const auto where = [&](const QString &column) {
            return tr("%1, %2").arg(config.name(), column);
        };
        const auto cob = number(text(CobId));
        if (!cob || *cob > 0x1FFFFFFF)
            return invalid(tr("%1: '%2' is no COB-ID").arg(where(tr("COB-ID")), text(CobId)));
        const bool on = m_table->item(row, Enabled)->checkState() == Qt::Checked;
        config.cobId = (config.cobId & (PdoConfig::kNoRtrBit)) | *cob
            | (*cob > 0x7FF ? PdoConfig::kExtendedBit : 0) | (on ? 0 : PdoConfig::kInvalidBit);
        const auto type = number(text(Type));
        if (!type || *type > 0xFF)
            return invalid(
                tr("%1: '%2' is no transmission type (0..255)").arg(where(tr("Type")), text(Type)));
        config.transmissionType = quint8(*type);
        for (const auto &[column, field, name] :
             { std::tuple { int(Inhibit), &config.inhibitTime, tr("Inhibit") },
               std::tuple { int(Event), &config.eventTimer, tr("Event") } }) {
            if (!field->has_value())
                continue; // the device has no such sub-index
            const auto v = number(text(column));
            if (!v || *v > 0xFFFF)
                return invalid(tr("%1: '%2' is not 0..65535").arg(where(name), text(column)));
            *field = quint16(*v);
        }
        auto entries = parseMapping(text(Mapping), dict);
        if (!entries)
            return entries.error().prefixed(where(tr("Mapping")));
        config.entries = *entries;
        configs.append(config);
    }
    return configs;
}

void PdoPanel::fill(const QList<PdoConfig> &configs)
{
    m_filling = true;
    m_configs = configs;
    const ObjectDictionary dict = dictionary();
    m_table->setRowCount(0);
    m_table->setRowCount(int(configs.size()));
    for (int row = 0; row < configs.size(); ++row) {
        const PdoConfig &c = configs.at(row);
        const auto set = [&](int column, const QString &text, bool editable = true) {
            auto *item = new QTableWidgetItem(text);
            if (!editable)
                item->setFlags(item->flags() & ~Qt::ItemIsEditable);
            m_table->setItem(row, column, item);
            return item;
        };
        QTableWidgetItem *name = set(Pdo, c.name(), false);
        name->setToolTip(tr("communication %1h, mapping %2h")
                             .arg(c.communicationIndex(), 4, 16, QLatin1Char('0'))
                             .arg(c.mappingIndex(), 4, 16, QLatin1Char('0')));
        QTableWidgetItem *on = set(Enabled, QString(), false);
        on->setFlags((on->flags() | Qt::ItemIsUserCheckable) & ~Qt::ItemIsEditable);
        on->setCheckState(c.isEnabled() ? Qt::Checked : Qt::Unchecked);
        set(CobId, hex(c.canId(), c.cobId & PdoConfig::kExtendedBit ? 8 : 3));
        set(Type, QString::number(c.transmissionType));
        set(Inhibit, c.inhibitTime ? QString::number(*c.inhibitTime) : tr("—"),
            c.inhibitTime.has_value());
        set(Event, c.eventTimer ? QString::number(*c.eventTimer) : tr("—"),
            c.eventTimer.has_value());
        QTableWidgetItem *mapping = set(Mapping, mappingText(c.entries));
        QStringList names; // the mapped objects by name, where the node's description has them
        for (const PdoMappingEntry &e : c.entries) {
            if (const ObjectDef *def = dict.find(e.address))
                names.append(QStringLiteral("%1 %2").arg(e.address.toString(), def->name));
        }
        mapping->setToolTip(names.join(QLatin1Char('\n')));
    }
    m_filling = false;
}

bool PdoPanel::read()
{
    if (m_busy || !m_client || !m_node || !m_network->isOpen())
        return false;
    setBusy(true);
    showStatus(tr("reading the PDOs of node %1…").arg(m_node), false);
    const canopen::NodeId node = m_node;
    Reply *reply = m_client->readAll(node, dictionary());
    connect(reply, &Reply::finished, this, [this, reply, node] {
        reply->deleteLater();
        if (node != m_node) { // another node was selected meanwhile: its table stays empty
            setBusy(false);
            Q_EMIT readFinished(false);
            return;
        }
        if (!reply->ok()) {
            setBusy(false);
            showStatus(tr("reading the PDOs failed: %1").arg(reply->error().message()), true);
            Q_EMIT readFinished(false);
            return;
        }
        const auto configs = reply->value().value<QList<PdoConfig>>();
        fill(configs);
        setBusy(false);
        showStatus(configs.isEmpty() ? tr("node %1 has no PDO objects").arg(m_node)
                                     : tr("%n PDO(s) read", nullptr, int(configs.size())),
                   false);
        Q_EMIT readFinished(true);
    });
    return true;
}

bool PdoPanel::write()
{
    if (m_busy || !m_client || !m_node)
        return false;
    auto parsed = edited();
    if (!parsed) {
        showStatus(parsed.error().message(), true);
        return false;
    }
    QList<PdoConfig> changed;
    for (int i = 0; i < parsed->size(); ++i) {
        if (!(parsed->at(i) == m_configs.at(i)))
            changed.append(parsed->at(i));
    }
    if (changed.isEmpty()) {
        showStatus(tr("nothing changed"), false);
        return false;
    }
    setBusy(true);
    writeNext(m_node, changed, 0);
    return true;
}

void PdoPanel::writeNext(canopen::NodeId node, QList<PdoConfig> todo, int written)
{
    if (todo.isEmpty()) {
        setBusy(false);
        showStatus(tr("%n PDO(s) written", nullptr, written), false);
        Q_EMIT writeFinished(true);
        if (node == m_node)
            read(); // what the node took
        return;
    }
    const PdoConfig config = todo.takeFirst();
    showStatus(tr("writing %1…").arg(config.name()), false);
    Reply *reply = m_client->configure(node, config);
    if (m_changeLog && m_network) {
        ChangeLog::Entry e;
        e.device = m_network->name();
        e.kind = ChangeLog::Kind::Write;
        e.object = tr("%1 of node %2").arg(config.name()).arg(node);
        for (const PdoConfig &old : std::as_const(m_configs)) {
            if (old.direction == config.direction && old.number == config.number)
                e.oldValue = old.toString();
        }
        e.newValue = config.toString();
        m_changeLog->track(e, reply);
    }
    connect(reply, &Reply::finished, this, [this, reply, node, config, todo, written] {
        reply->deleteLater();
        if (!reply->ok()) {
            setBusy(false);
            showStatus(tr("%1 not written (it stays disabled): %2")
                           .arg(config.name(), reply->error().message()),
                       true);
            Q_EMIT writeFinished(false);
            return;
        }
        writeNext(node, todo, written + 1);
    });
}

void PdoPanel::setBusy(bool busy)
{
    m_busy = busy;
    m_readButton->setEnabled(!busy && m_client && m_node);
    m_writeButton->setEnabled(!busy && m_client && m_node && !m_configs.isEmpty());
    m_table->setEnabled(!busy);
}

QString PdoPanel::status() const
{
    return m_status->text();
}

void PdoPanel::showStatus(const QString &text, bool error)
{
    m_status->setText(text);
    style::setTextColor(m_status, error ? style::errorColor() : QColor());
}

} // namespace db::widgets
