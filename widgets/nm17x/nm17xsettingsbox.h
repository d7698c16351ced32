#pragma once

// The operating modes and settings of the display selected in the NM17x line panel, by SDO:
// what the external inputs F/G do (2041h:03), how the keys drive (2041h:04), oscillation between
// D1 and D2 (204Dh:02), the scaling from the spindle pitch (2004h), the jump filter (2005h:01/02)
// and the dynamic pre-shutdown (2041h:02) with the switch-off point it adapts (2042h:03).
// Selecting a display reads its current values; until a value has come, its field is blank and
// its command disabled (a failed read leaves the field blank and lets the user enter a value).
// The motor settings are disabled on an NM170.

#include "canopen/canopenids.h"
#include "devices/nm17x/nm17xdescription.h"

#include <QPointer>
#include <QSet>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace db {
class Reply;
}
namespace db::nm17x {
class Nm17xLine;
}

namespace db::widgets {

class Nm17xSettingsBox : public QWidget
{
    Q_OBJECT
public:
    explicit Nm17xSettingsBox(QWidget *parent = nullptr);

    // The display to work on; a null line or node 0 disables the box. Reads its settings.
    void setDisplay(nm17x::Nm17xLine *line, canopen::NodeId node, nm17x::Variant variant);
    canopen::NodeId node() const { return m_node; }
    // The switch-off point 2042h:03 as last read (1/100 mm); the pre-shutdown adapts it.
    QString switchOffText() const;

public Q_SLOTS:
    void refresh();
    void setInputMode(int mode);
    void setKeyMode(int mode);
    void oscillate(bool on);
    void setScaling();
    void setJumpFilter();
    void setPreShutdown(bool on);

Q_SIGNALS:
    // The outcome of a command ("node 3: 2041h:03 = 1 (Takten)", or why it failed).
    void message(const QString &text);

private:
    void write(ObjectAddress address, qint64 value, const QString &what);
    void read(ObjectAddress address);
    void show(ObjectAddress address, qint64 value);
    void updateEnabled();
    void clearValues();
    // A value read, or a read that failed: the field is no longer waiting for the display.
    bool settled(ObjectAddress address) const { return m_settled.contains(address); }

    QPointer<nm17x::Nm17xLine> m_line;
    canopen::NodeId m_node = 0;
    nm17x::Variant m_variant = nm17x::Variant::Nm172;
    int m_generation = 0; // answers for an earlier selection are dropped
    QComboBox *m_inputs;
    QComboBox *m_keys;
    QPushButton *m_oscStart;
    QPushButton *m_oscStop;
    QDoubleSpinBox *m_pitch;
    QSpinBox *m_steps;
    QPushButton *m_setScaling;
    QLabel *m_scaling;
    QSpinBox *m_filterWidth;
    QSpinBox *m_filterCount;
    QPushButton *m_setFilter;
    QCheckBox *m_preShutdown;
    QLabel *m_switchOff;
    QSet<ObjectAddress> m_settled;
};

} // namespace db::widgets
