#include "nm17xsettingsbox.h"

#include "core/reply.h"
#include "devices/nm17x/nm17xline.h"
#include "widgets/common/flowlayout.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>

namespace db::widgets {

using namespace db::nm17x;

namespace {
constexpr ObjectAddress kInputMode { 0x2041, 3 };
constexpr ObjectAddress kKeyMode { 0x2041, 4 };
constexpr ObjectAddress kPreShutdown { 0x2041, 2 };
constexpr ObjectAddress kOscillation { 0x204D, 2 };
constexpr ObjectAddress kScaling { 0x2004, 0 };
constexpr ObjectAddress kFilterWidth { 0x2005, 1 };
constexpr ObjectAddress kFilterCount { 0x2005, 2 };
constexpr ObjectAddress kSwitchOff { 0x2042, 3 };

// The names the description gives to an enumerated object's values.
void fillFrom(QComboBox *box, ObjectAddress address)
{
    const ObjectDictionary all = dictionary(Variant::Nm174);
    if (const ObjectDef *def = all.find(address)) {
        const auto names = def->displayEnumeration();
        for (auto it = names.cbegin(); it != names.cend(); ++it)
            box->addItem(it.value(), int(it.key()));
    }
}
} // namespace

Nm17xSettingsBox::Nm17xSettingsBox(QWidget *parent)
    : QWidget(parent)
    , m_inputs(new QComboBox(this))
    , m_keys(new QComboBox(this))
    , m_oscStart(new QPushButton(tr("Oscillate"), this))
    , m_oscStop(new QPushButton(tr("Stop oscillating"), this))
    , m_pitch(new QDoubleSpinBox(this))
    , m_steps(new QSpinBox(this))
    , m_setScaling(new QPushButton(tr("Set scaling"), this))
    , m_scaling(new QLabel(this))
    , m_filterWidth(new QSpinBox(this))
    , m_filterCount(new QSpinBox(this))
    , m_setFilter(new QPushButton(tr("Set filter"), this))
    , m_preShutdown(new QCheckBox(tr("Dynamic pre-shutdown"), this))
    , m_switchOff(new QLabel(this))
{
    fillFrom(m_inputs, kInputMode);
    fillFrom(m_keys, kKeyMode);
    m_pitch->setRange(0.01, 999.99);
    m_pitch->setDecimals(2);
    m_pitch->setValue(4.0);
    m_pitch->setSuffix(tr(" mm/rev"));
    m_steps->setRange(1, 1 << 24);
    m_steps->setValue(stepsPerRevolution(Variant::Nm172));
    m_steps->setSuffix(tr(" steps/rev"));
    m_filterWidth->setRange(0, 2303);
    m_filterWidth->setSuffix(tr(" steps"));
    m_filterCount->setRange(0, 99);
    m_filterCount->setSuffix(tr(" jumps"));
    m_inputs->setToolTip(tr("What the external inputs F and G do"));
    m_keys->setToolTip(tr("How the device keys drive the motor"));
    m_filterWidth->setToolTip(tr("Position jumps larger than this are filtered out"));
    m_filterCount->setToolTip(tr("Consecutive jumps filtered before one is taken as real"));
    m_preShutdown->setToolTip(tr("After each positioning, half the distance by which the target "
                                 "was missed moves the switch-off point"));
    const std::pair<QWidget *, const char *> names[] = {
        { m_inputs, "inputMode" },
        { m_keys, "keyMode" },
        { m_oscStart, "oscillate" },
        { m_oscStop, "stopOscillating" },
        { m_pitch, "pitch" },
        { m_steps, "stepsPerRevolution" },
        { m_setScaling, "setScaling" },
        { m_scaling, "scaling" },
        { m_filterWidth, "filterWidth" },
        { m_filterCount, "filterCount" },
        { m_setFilter, "setFilter" },
        { m_preShutdown, "preShutdown" },
        { m_switchOff, "switchOff" },
    };
    for (const auto &[widget, name] : names)
        widget->setObjectName(QLatin1String(name));

    connect(m_inputs, &QComboBox::activated, this,
            [this](int i) { setInputMode(m_inputs->itemData(i).toInt()); });
    connect(m_keys, &QComboBox::activated, this,
            [this](int i) { setKeyMode(m_keys->itemData(i).toInt()); });
    connect(m_oscStart, &QPushButton::clicked, this, [this] { oscillate(true); });
    connect(m_oscStop, &QPushButton::clicked, this, [this] { oscillate(false); });
    connect(m_setScaling, &QPushButton::clicked, this, &Nm17xSettingsBox::setScaling);
    connect(m_setFilter, &QPushButton::clicked, this, &Nm17xSettingsBox::setJumpFilter);
    connect(m_preShutdown, &QCheckBox::clicked, this, &Nm17xSettingsBox::setPreShutdown);

    // Groups that keep together; the rows wrap in a narrow dock.
    const auto group = [this](std::initializer_list<QWidget *> widgets) {
        auto *box = new QWidget(this);
        auto *row = new QHBoxLayout(box);
        row->setContentsMargins(0, 0, 0, 0);
        for (QWidget *w : widgets)
            row->addWidget(w);
        return box;
    };
    auto *flow = new FlowLayout(this);
    flow->setContentsMargins(0, 0, 0, 0);
    flow->addWidget(group({ new QLabel(tr("Inputs F/G:"), this), m_inputs }));
    flow->addWidget(group({ new QLabel(tr("Keys:"), this), m_keys }));
    flow->addWidget(group({ m_oscStart, m_oscStop }));
    flow->addWidget(group({ m_preShutdown, m_switchOff }));
    flow->addWidget(group({ new QLabel(tr("Pitch:"), this), m_pitch, m_steps, m_setScaling }));
    flow->addWidget(m_scaling);
    flow->addWidget(
        group({ new QLabel(tr("Jump filter:"), this), m_filterWidth, m_filterCount, m_setFilter }));
    updateEnabled();
}

void Nm17xSettingsBox::setDisplay(Nm17xLine *line, canopen::NodeId node, Variant variant)
{
    const bool changed = line != m_line || node != m_node || variant != m_variant;
    m_line = line;
    m_node = node;
    m_variant = variant;
    if (changed) {
        ++m_generation;
        m_steps->setValue(stepsPerRevolution(variant));
        clearValues();
    }
    updateEnabled();
    if (changed)
        refresh();
}

// Blank until this display's own values have been read, never the previous one's.
void Nm17xSettingsBox::clearValues()
{
    m_settled.clear();
    m_scaling->clear();
    m_switchOff->clear();
    m_inputs->setCurrentIndex(-1);
    m_keys->setCurrentIndex(-1);
    m_pitch->clear();
    m_filterWidth->clear();
    m_filterCount->clear();
    m_preShutdown->setTristate(true);
    m_preShutdown->setCheckState(Qt::PartiallyChecked);
}

QString Nm17xSettingsBox::switchOffText() const
{
    return m_switchOff->text();
}

void Nm17xSettingsBox::updateEnabled()
{
    const bool on = m_line && m_node != 0;
    const bool motor = on && hasMotor(m_variant);
    for (QWidget *w : std::initializer_list<QWidget *> { m_inputs, m_keys, m_oscStart, m_oscStop })
        w->setEnabled(motor);
    m_preShutdown->setEnabled(motor && settled(kPreShutdown));
    for (QWidget *w : std::initializer_list<QWidget *> { m_pitch, m_steps, m_setScaling })
        w->setEnabled(on && settled(kScaling));
    for (QWidget *w :
         std::initializer_list<QWidget *> { m_filterWidth, m_filterCount, m_setFilter })
        w->setEnabled(on && settled(kFilterWidth) && settled(kFilterCount));
}

void Nm17xSettingsBox::refresh()
{
    if (!m_line || m_node == 0)
        return;
    read(kScaling);
    read(kFilterWidth);
    read(kFilterCount);
    if (!hasMotor(m_variant))
        return;
    for (const ObjectAddress a : { kInputMode, kKeyMode, kPreShutdown, kSwitchOff })
        read(a);
}

void Nm17xSettingsBox::read(ObjectAddress address)
{
    Reply *reply = m_line->read(m_node, address);
    reply->setParent(this); // dies with the box when it goes first
    const int generation = m_generation;
    connect(reply, &Reply::finished, this, [this, reply, address, generation] {
        reply->deleteLater();
        if (generation != m_generation)
            return;
        m_settled.insert(address);
        if (reply->ok())
            show(address, reply->value().toLongLong());
        else
            Q_EMIT message(reply->error().message());
        updateEnabled();
    });
}

void Nm17xSettingsBox::show(ObjectAddress address, qint64 value)
{
    const auto select = [](QComboBox *box, qint64 v) {
        const int i = box->findData(int(v));
        if (i >= 0)
            box->setCurrentIndex(i);
    };
    if (address == kInputMode) {
        select(m_inputs, value);
    } else if (address == kKeyMode) {
        select(m_keys, value);
    } else if (address == kPreShutdown) {
        m_preShutdown->setTristate(false);
        m_preShutdown->setChecked(value == 1);
    } else if (address == kSwitchOff) {
        m_switchOff->setText(tr("switch-off point %1").arg(formatPosition(qint32(value), false)));
    } else if (address == kScaling) {
        const double pitch = pitchOf(quint32(value), m_steps->value());
        m_scaling->setText(tr("%1 = %2 mm/rev").arg(value).arg(pitch / 100.0, 0, 'f', 2));
        m_pitch->setValue(pitch / 100.0);
    } else if (address == kFilterWidth) {
        m_filterWidth->setValue(int(value));
    } else if (address == kFilterCount) {
        m_filterCount->setValue(int(value));
    }
}

void Nm17xSettingsBox::write(ObjectAddress address, qint64 value, const QString &what)
{
    if (!m_line || m_node == 0)
        return;
    Reply *reply = m_line->write(m_node, address, value);
    reply->setParent(this);
    const canopen::NodeId node = m_node;
    const int generation = m_generation;
    connect(reply, &Reply::finished, this, [this, reply, address, node, what, generation] {
        reply->deleteLater();
        Q_EMIT message(reply->ok() ? tr("node %1: %2").arg(node).arg(what)
                                   : reply->error().message());
        if (generation == m_generation)
            read(address); // show what the display took
    });
}

void Nm17xSettingsBox::setInputMode(int mode)
{
    write(kInputMode, mode, tr("inputs F/G: %1").arg(m_inputs->itemText(m_inputs->findData(mode))));
}

void Nm17xSettingsBox::setKeyMode(int mode)
{
    write(kKeyMode, mode, tr("keys: %1").arg(m_keys->itemText(m_keys->findData(mode))));
}

void Nm17xSettingsBox::oscillate(bool on)
{
    if (!m_line || m_node == 0)
        return;
    Reply *reply = m_line->write(m_node, kOscillation, on ? 1 : 0);
    reply->setParent(this);
    const canopen::NodeId node = m_node;
    connect(reply, &Reply::finished, this, [this, reply, node, on] {
        reply->deleteLater();
        Q_EMIT message(reply->ok() ? (on ? tr("node %1: oscillating between D1 and D2").arg(node)
                                         : tr("node %1: oscillation stopped").arg(node))
                                   : reply->error().message());
    });
}

void Nm17xSettingsBox::setScaling()
{
    if (m_pitch->cleanText().isEmpty()) {
        Q_EMIT message(tr("Enter the spindle pitch first: the display's scaling could not be "
                          "read."));
        return;
    }
    const qint32 pitch = qint32(qRound(m_pitch->value() * 100));
    const quint32 scaling = scalingFor(pitch, m_steps->value());
    write(kScaling, scaling,
          tr("scaling %1 (%2 mm/rev, %3 steps/rev)")
              .arg(scaling)
              .arg(m_pitch->value(), 0, 'f', 2)
              .arg(m_steps->value()));
}

void Nm17xSettingsBox::setJumpFilter()
{
    if (m_filterWidth->cleanText().isEmpty() || m_filterCount->cleanText().isEmpty()) {
        Q_EMIT message(tr("Enter the jump filter's width and count first: the display's filter "
                          "could not be read."));
        return;
    }
    write(kFilterWidth, m_filterWidth->value(),
          tr("jump filter %1 steps").arg(m_filterWidth->value()));
    write(kFilterCount, m_filterCount->value(),
          tr("jump filter count %1").arg(m_filterCount->value()));
}

void Nm17xSettingsBox::setPreShutdown(bool on)
{
    write(kPreShutdown, on ? 1 : 0,
          on ? tr("dynamic pre-shutdown on") : tr("dynamic pre-shutdown off"));
}

} // namespace db::widgets
