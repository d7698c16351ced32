#pragma once

#include "core/objectdef.h"

#include <QWidget>

class QGridLayout;
class QLabel;

namespace db::widgets {

class Lamp;

// The details of the object selected in the editor: address, name, type, description and, for
// words with named bits (6040h, 6041h, 1002h, 60FDh, ...), one lamp per bit with its state.
// Bit names come from the object's description; 6040h, 6041h and 60FDh fall back to the CiA 402
// names when the description has none.
class OdBitFieldView : public QWidget
{
    Q_OBJECT
public:
    explicit OdBitFieldView(QWidget *parent = nullptr);

    // def null: nothing selected. Rebuilds the lamps only when the object changes.
    void setObject(const ObjectDef *def);
    // The object's current raw value (invalid: unknown, lamps drawn stale).
    void setValue(const QVariant &raw);

    // The bit fields shown for def: its own, else the CiA 402 ones for its address.
    static QList<BitField> bitFieldsFor(const ObjectDef &def);
    // For tests: lamp of bit `bit`, null when not shown.
    Lamp *lamp(int bit) const;
    QString fieldText(int bit) const; // multi-bit fields: "4-6 Mode bits = 3"

private:
    void clearBits();

    std::optional<ObjectDef> m_def;
    QList<BitField> m_fields;
    QLabel *m_title;
    QLabel *m_description;
    QWidget *m_bitsBox;
    QGridLayout *m_bitsGrid;
    QList<QWidget *> m_bitWidgets; // per field: Lamp (width 1) or QLabel
};

} // namespace db::widgets
