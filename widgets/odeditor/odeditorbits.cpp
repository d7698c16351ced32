#include "odeditorbits.h"

#include "widgets/common/lamp.h"
#include "widgets/common/widgetstyle.h"

#include <QGridLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace db::widgets {

namespace {
constexpr int kBitColumns = 4;

// CiA 402-2 (controlword, statusword) and CiA 402 60FDh digital inputs.
QList<BitField> cia402Fields(quint16 index)
{
    const auto list = [](std::initializer_list<std::pair<int, const char *>> bits) {
        QList<BitField> fields;
        for (const auto &[bit, name] : bits)
            fields.append({ bit, 1, OdBitFieldView::tr(name) });
        return fields;
    };
    switch (index) {
    case 0x6040:
        return list(
            { { 0, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Switch on") },
              { 1, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Enable voltage") },
              { 2, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Quick stop") },
              { 3, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Enable operation") },
              { 4, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Operation mode specific") },
              { 5, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Operation mode specific") },
              { 6, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Operation mode specific") },
              { 7, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Fault reset") },
              { 8, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Halt") },
              { 9, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Operation mode specific") } });
    case 0x6041:
        return list(
            { { 0, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Ready to switch on") },
              { 1, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Switched on") },
              { 2, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Operation enabled") },
              { 3, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Fault") },
              { 4, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Voltage enabled") },
              { 5, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Quick stop") },
              { 6, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Switch on disabled") },
              { 7, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Warning") },
              { 9, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Remote") },
              { 10, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Target reached") },
              { 11, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Internal limit active") },
              { 12, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Operation mode specific") },
              { 13,
                QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Operation mode specific") } });
    case 0x60FD:
        return list(
            { { 0, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Negative limit switch") },
              { 1, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Positive limit switch") },
              { 2, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Home switch") },
              { 3, QT_TRANSLATE_NOOP("db::widgets::OdBitFieldView", "Interlock") } });
    default:
        return {};
    }
}
} // namespace

OdBitFieldView::OdBitFieldView(QWidget *parent)
    : QWidget(parent)
    , m_title(new QLabel(this))
    , m_description(new QLabel(this))
    , m_bitsBox(new QWidget(this))
    , m_bitsGrid(new QGridLayout(m_bitsBox))
{
    m_title->setObjectName(QStringLiteral("detailsTitle"));
    m_description->setObjectName(QStringLiteral("detailsDescription"));
    m_title->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_description->setWordWrap(true);
    m_description->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_description->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    m_bitsGrid->setContentsMargins(0, 4, 0, 0);
    m_bitsGrid->setHorizontalSpacing(18);
    m_bitsGrid->setVerticalSpacing(2);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(m_description);
    layout->addWidget(m_bitsBox);
    layout->addStretch();
    setObject(nullptr);
}

QList<BitField> OdBitFieldView::bitFieldsFor(const ObjectDef &def)
{
    if (!def.bitFields.isEmpty())
        return def.bitFields;
    if (def.address.sub == 0)
        return cia402Fields(def.address.index);
    return {};
}

void OdBitFieldView::clearBits()
{
    qDeleteAll(m_bitWidgets);
    m_bitWidgets.clear();
    m_fields.clear();
}

void OdBitFieldView::setObject(const ObjectDef *def)
{
    if (def && m_def && m_def->address == def->address)
        return;
    clearBits();
    if (!def) {
        m_def.reset();
        m_title->setText(tr("Select an object to see its details."));
        style::setTextColor(m_title, style::inactiveColor());
        m_description->clear();
        m_bitsBox->hide();
        return;
    }
    m_def = *def;
    style::setTextColor(m_title, QColor());
    QString title =
        QStringLiteral("<b>%1</b> &nbsp;%2")
            .arg(m_addressFormat->format(def->address),
                 (def->objectName.isEmpty() || def->objectName == def->name
                      ? def->displayName()
                      : def->displayObjectName() + QStringLiteral(" / ") + def->displayName())
                     .toHtmlEscaped());
    title +=
        QStringLiteral(" &nbsp;<span style='color:gray'>%1, %2%3%4</span>")
            .arg(datatype::name(def->type), access::name(def->access),
                 def->unit.isEmpty() ? QString()
                                     : QStringLiteral(", ") + def->displayUnit().toHtmlEscaped(),
                 def->storable ? tr(", storable") : QString());
    m_title->setText(title);
    m_description->setText(def->description);
    m_description->setVisible(!def->description.isEmpty());

    m_fields = bitFieldsFor(*def);
    for (int i = 0; i < m_fields.size(); ++i) {
        const BitField &f = m_fields[i];
        QWidget *w = nullptr;
        if (f.width == 1) {
            w = new Lamp(QStringLiteral("%1  %2").arg(f.bit, 2).arg(f.displayName()),
                         style::okColor(), m_bitsBox);
        } else {
            w = new QLabel(m_bitsBox);
        }
        // The English name beside the shown one: the term of the English manuals and files.
        w->setToolTip(f.displayName() == f.name
                          ? f.name
                          : QStringLiteral("%1 (%2)").arg(f.displayName(), f.name));
        m_bitsGrid->addWidget(w, i % ((m_fields.size() + kBitColumns - 1) / kBitColumns),
                              i / ((m_fields.size() + kBitColumns - 1) / kBitColumns));
        m_bitWidgets.append(w);
    }
    m_bitsBox->setVisible(!m_fields.isEmpty());
    setValue({});
}

void OdBitFieldView::setValue(const QVariant &raw)
{
    const bool known = raw.isValid();
    const quint64 bits = raw.toULongLong();
    for (int i = 0; i < m_fields.size(); ++i) {
        const BitField &f = m_fields[i];
        const quint64 mask = f.width >= 64 ? ~0ull : ((1ull << f.width) - 1);
        const quint64 v = (bits >> f.bit) & mask;
        if (auto *lamp = qobject_cast<Lamp *>(m_bitWidgets[i])) {
            if (known)
                lamp->setOn(v != 0);
            else
                lamp->setStale(true);
        } else if (auto *label = qobject_cast<QLabel *>(m_bitWidgets[i])) {
            label->setText(
                QStringLiteral("%1-%2  %3 = %4")
                    .arg(f.bit)
                    .arg(f.bit + f.width - 1)
                    .arg(f.displayName(), known ? QString::number(v) : QStringLiteral("?")));
        }
    }
}

Lamp *OdBitFieldView::lamp(int bit) const
{
    for (int i = 0; i < m_fields.size(); ++i) {
        if (m_fields[i].bit == bit)
            return qobject_cast<Lamp *>(m_bitWidgets[i]);
    }
    return nullptr;
}

QString OdBitFieldView::fieldText(int bit) const
{
    for (int i = 0; i < m_fields.size(); ++i) {
        if (m_fields[i].bit == bit) {
            if (auto *label = qobject_cast<QLabel *>(m_bitWidgets[i]))
                return label->text();
        }
    }
    return {};
}

} // namespace db::widgets
