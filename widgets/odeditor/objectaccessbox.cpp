#include "objectaccessbox.h"

#include "widgets/common/widgetstyle.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>

namespace db::widgets {

namespace {
// Unknown objects without a picked type are read and written as a 64-bit integer; the
// connection then sends the value as given.
constexpr DataType kAutoType = DataType::Integer64;
} // namespace

ObjectAccessBox::ObjectAccessBox(QWidget *parent)
    : QWidget(parent)
    , m_address(new QLineEdit(this))
    , m_type(new QComboBox(this))
    , m_info(new QLabel(this))
    , m_value(new QLineEdit(this))
    , m_hex(new QCheckBox(tr("He&x"), this))
    , m_readButton(new QPushButton(tr("&Read"), this))
    , m_writeButton(new QPushButton(tr("&Write"), this))
    , m_progress(new QProgressBar(this))
    , m_result(new QLabel(this))
{
    m_address->setObjectName(QStringLiteral("address"));
    m_type->setObjectName(QStringLiteral("type"));
    m_info->setObjectName(QStringLiteral("info"));
    m_value->setObjectName(QStringLiteral("value"));
    m_hex->setObjectName(QStringLiteral("hex"));
    m_readButton->setObjectName(QStringLiteral("read"));
    m_writeButton->setObjectName(QStringLiteral("write"));
    m_result->setObjectName(QStringLiteral("result"));

    m_address->setFont(style::monospaceFont());
    m_address->setPlaceholderText(QStringLiteral("6041:0"));
    m_address->setMaxLength(16);
    m_address->setMaximumWidth(
        QFontMetrics(style::monospaceFont()).horizontalAdvance(QStringLiteral("0x6041:0x00")) + 24);
    m_type->addItem(tr("auto (integer)"), QVariant::fromValue(kAutoType));
    for (DataType type : datatype::all())
        m_type->addItem(datatype::name(type), QVariant::fromValue(type));
    m_type->setToolTip(tr("Data type for objects the device description does not know"));
    m_info->setWordWrap(true);
    m_info->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_value->setFont(style::monospaceFont());
    m_value->setPlaceholderText(tr("value"));
    m_progress->setRange(0, 0);
    m_progress->setTextVisible(false);
    m_progress->setMaximumSize(60, 12);
    m_progress->setVisible(false);
    QSizePolicy keep = m_progress->sizePolicy();
    keep.setRetainSizeWhenHidden(true);
    m_progress->setSizePolicy(keep);
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_result->setMinimumHeight(m_result->fontMetrics().height() * 2);
    m_result->setAlignment(Qt::AlignLeft | Qt::AlignTop);

    auto *grid = new QGridLayout(this);
    grid->addWidget(new QLabel(tr("Object:"), this), 0, 0);
    auto *addressRow = new QHBoxLayout;
    addressRow->addWidget(m_address);
    addressRow->addWidget(m_type, 1);
    addressRow->addStretch();
    grid->addLayout(addressRow, 0, 1);
    grid->addWidget(m_info, 1, 1);
    grid->addWidget(new QLabel(tr("Value:"), this), 2, 0);
    auto *valueRow = new QHBoxLayout;
    valueRow->addWidget(m_value, 1);
    valueRow->addWidget(m_hex);
    grid->addLayout(valueRow, 2, 1);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_readButton);
    buttons->addWidget(m_writeButton);
    buttons->addWidget(m_progress);
    buttons->addStretch();
    grid->addLayout(buttons, 3, 1);
    grid->addWidget(m_result, 4, 1);
    grid->setColumnStretch(1, 1);
    grid->setRowStretch(5, 1);

    connect(m_address, &QLineEdit::textChanged, this, &ObjectAccessBox::updateInfo);
    connect(m_type, &QComboBox::currentIndexChanged, this, &ObjectAccessBox::updateInfo);
    connect(m_address, &QLineEdit::returnPressed, this, &ObjectAccessBox::read);
    connect(m_value, &QLineEdit::returnPressed, this, &ObjectAccessBox::write);
    connect(m_hex, &QCheckBox::toggled, this, &ObjectAccessBox::showValue);
    connect(m_readButton, &QPushButton::clicked, this, &ObjectAccessBox::read);
    connect(m_writeButton, &QPushButton::clicked, this, &ObjectAccessBox::write);
    updateInfo();
}

void ObjectAccessBox::setConnection(DeviceConnection *connection)
{
    if (connection && m_connection == connection)
        return;
    for (const auto &c : std::as_const(m_connectionSignals))
        disconnect(c);
    m_connectionSignals.clear();
    ++m_generation;
    setBusy(false);
    m_connection = connection;
    m_address->setPlaceholderText(addressFormat().example());
    if (connection) {
        m_connectionSignals = {
            connect(connection, &DeviceConnection::stateChanged, this,
                    &ObjectAccessBox::updateActions),
            // A destroyed connection is forgotten as if setConnection(nullptr) was called.
            connect(connection, &QObject::destroyed, this, [this] { setConnection(nullptr); }),
        };
    }
    updateInfo();
}

const AddressFormat &ObjectAccessBox::addressFormat() const
{
    return m_connection ? m_connection->addressFormat() : AddressFormat::canopen();
}

QString ObjectAccessBox::addressText() const
{
    return m_address->text();
}

void ObjectAccessBox::setAddressText(const QString &text)
{
    m_address->setText(text);
}

QString ObjectAccessBox::valueText() const
{
    return m_value->text();
}

void ObjectAccessBox::setValueText(const QString &text)
{
    m_value->setText(text);
}

bool ObjectAccessBox::isHex() const
{
    return m_hex->isChecked();
}

void ObjectAccessBox::setHex(bool hex)
{
    m_hex->setChecked(hex);
}

QString ObjectAccessBox::resultText() const
{
    return m_result->text();
}

std::optional<ObjectDef> ObjectAccessBox::currentDefinition() const
{
    auto address = addressFormat().parse(m_address->text());
    if (!address)
        return std::nullopt;
    if (m_connection) {
        if (const ObjectDef *def = m_connection->dictionary().find(address.value()))
            return *def;
    }
    ObjectDef def;
    def.address = address.value();
    def.type = m_type->currentData().value<DataType>();
    def.access = Access::ReadWrite;
    return def;
}

void ObjectAccessBox::updateInfo()
{
    const QString text = m_address->text().trimmed();
    auto address = addressFormat().parse(text);
    const ObjectDef *known =
        (address && m_connection) ? m_connection->dictionary().find(address.value()) : nullptr;
    m_type->setVisible(address && !known);
    if (text.isEmpty()) {
        m_info->setText(tr("Enter an object address, e.g. %1").arg(addressFormat().example()));
        style::setTextColor(m_info, style::inactiveColor());
    } else if (!address) {
        m_info->setText(address.error().message());
        style::setTextColor(m_info, style::errorColor());
    } else if (known) {
        QString info = QStringLiteral("<b>%1</b>")
                           .arg((known->objectName.isEmpty() ? known->displayName()
                                                             : known->displayObjectName()
                                         + QStringLiteral(" / ") + known->displayName())
                                    .toHtmlEscaped());
        info += tr("<br>%1, %2").arg(datatype::name(known->type), access::name(known->access));
        if (!known->unit.isEmpty())
            info += tr(", unit %1").arg(known->displayUnit().toHtmlEscaped());
        m_info->setText(info);
        m_info->setToolTip(style::toolTip(known->description));
        style::setTextColor(m_info, QColor());
    } else {
        m_info->setText(tr("%1 is not in the device description; it is read as an integer, "
                           "or as the type you pick.")
                            .arg(addressFormat().format(*address)));
        m_info->setToolTip(QString());
        style::setTextColor(m_info, style::warningColor());
    }
    updateActions();
}

void ObjectAccessBox::updateActions()
{
    const auto def = currentDefinition();
    const bool connected = m_connection && m_connection->isConnected();
    m_readButton->setEnabled(connected && !m_busy && def && def->readable());
    m_writeButton->setEnabled(connected && !m_busy && def && def->writable());
    m_writeButton->setToolTip(def && !def->writable() ? tr("This object is read-only") : QString());
}

void ObjectAccessBox::setBusy(bool busy)
{
    m_busy = busy;
    m_progress->setVisible(busy);
    updateActions();
}

void ObjectAccessBox::showResult(bool ok, const QString &text)
{
    m_result->setText(text);
    style::setTextColor(m_result, ok ? style::okColor() : style::errorColor());
}

void ObjectAccessBox::read()
{
    auto address = addressFormat().parse(m_address->text());
    if (!address) {
        showResult(false, address.error().toString());
        Q_EMIT finished(false);
        return;
    }
    if (!m_connection || !m_connection->isConnected()) {
        showResult(false, tr("not connected"));
        Q_EMIT finished(false);
        return;
    }
    Reply *reply = m_connection->read(address.value());
    reply->setParent(this);
    setBusy(true);
    m_result->clear();
    const quint64 generation = m_generation;
    connect(reply, &Reply::finished, this,
            [this, reply, generation] { onReplyFinished(reply, true, generation); });
}

void ObjectAccessBox::write()
{
    const auto def = currentDefinition();
    if (!def) {
        showResult(false, addressFormat().parse(m_address->text()).error().toString());
        Q_EMIT finished(false);
        return;
    }
    if (!def->writable()) {
        showResult(
            false,
            tr("%1 %2 is read-only").arg(addressFormat().format(def->address), def->displayName()));
        Q_EMIT finished(false);
        return;
    }
    auto raw = def->parseText(m_value->text(), addressFormat());
    if (!raw) {
        showResult(false, raw.error().toString());
        Q_EMIT finished(false);
        return;
    }
    if (!m_connection || !m_connection->isConnected()) {
        showResult(false, tr("not connected"));
        Q_EMIT finished(false);
        return;
    }
    Reply *reply = m_connection->write(def->address, raw.value());
    reply->setParent(this);
    if (m_changeLog)
        m_changeLog->track(ChangeLog::writeEntry(*m_connection, def->address, QString(),
                                                 def->displayText(raw.value())),
                           reply);
    m_lastRaw = raw.value();
    setBusy(true);
    m_result->clear();
    const quint64 generation = m_generation;
    connect(reply, &Reply::finished, this,
            [this, reply, generation] { onReplyFinished(reply, false, generation); });
}

void ObjectAccessBox::onReplyFinished(Reply *reply, bool isRead, quint64 generation)
{
    reply->deleteLater();
    if (generation != m_generation)
        return;
    setBusy(false);
    if (!reply->ok()) {
        showResult(false, reply->error().toString());
        Q_EMIT finished(false);
        return;
    }
    const auto def = currentDefinition();
    if (isRead)
        m_lastRaw = reply->value();
    if (isRead)
        showValue();
    const QString shown = def ? def->localDisplayText(m_lastRaw) : m_lastRaw.toString();
    showResult(true, isRead ? tr("read %1").arg(shown) : tr("written %1").arg(shown));
    Q_EMIT finished(true);
}

void ObjectAccessBox::showValue()
{
    if (!m_lastRaw.isValid())
        return;
    const auto def = currentDefinition();
    const DataType type = def ? def->type : kAutoType;
    const auto format = isHex() ? codec::TextFormat::Hex : codec::TextFormat::Decimal;
    if (type == kAutoType && isHex() && m_lastRaw.toLongLong() >= 0)
        m_value->setText(QStringLiteral("0x")
                         + QString::number(m_lastRaw.toULongLong(), 16).toUpper());
    else
        m_value->setText(codec::toText(type, m_lastRaw, format));
}

} // namespace db::widgets
