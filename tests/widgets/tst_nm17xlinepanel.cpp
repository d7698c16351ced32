// The NM17x line panel offscreen against simulated displays on a scripted bus: finding the
// displays, live positions from TxPDO2, a setpoint with release, jog and stop, broadcasts.
#include "devices/nm17x/device/nm17xsim.h"
#include "devices/nm17x/device/simulatednm17x.h"
#include "devices/nm17x/nm17xcodes.h"
#include "scriptedcanbus.h"
#include "widgets/nm17x/nm17xaddressingdialog.h"
#include "widgets/nm17x/nm17xlinemodel.h"
#include "widgets/nm17x/nm17xlinepanel.h"
#include "widgets/nm17x/nm17xsettingsbox.h"

#include "canopen/cannetwork.h"
#include "canopen/canopenconnection.h"
#include "canopen/sdoclient.h"
#include "widgets/canopen/canmonitor.h"
#include "widgets/canopen/canmonitormodel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTableView>
#include <QTest>

using namespace db;
using namespace db::nm17x;

class TstNm17xLinePanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();
    void findsTheDisplays();
    void setpointWithReleaseReachesInPosition();
    void jogAndStop();
    void broadcastsReachEveryDisplay();
    void withoutNetworkNothingIsEnabled();
    void canMonitorNamesThePdoFieldsOfTheLine();
    void guidedAddressingAlongTheLine();
    void guidedAddressingTimeoutIsNamedPerStep();
    void modesOfTheSelectedDisplay();
    void settingsOfTheSelectedDisplay();
    void settingsOfAnotherDisplayAreBlankUntilRead();
    void scanFindsTheDisplaysAtTheirBitrate();
    void displayErrorsAreNamed();
    void unreadableErrorWordIsNotShownAsNoError();
    void nm170HasNoMotorSettings();
    void screenshotOfARunningLine();

private:
    // Finds the displays and sends node 3 (the NM172, whose shaft is blocked) a setpoint with
    // release: its following error (Er 3) comes 0.3 s later.
    bool sendToABlockedShaft(SimulatedNm17x **nm172);
    QPushButton *button(const char *name) { return m_panel->findChild<QPushButton *>(name); }
    QString cell(int row, int column)
    {
        return m_panel->model()->index(row, column).data().toString();
    }

    test::ScriptedCanBus *m_bus = nullptr;
    std::unique_ptr<canopen::CanNetwork> m_network;
    QList<SimulatedNm17x *> m_displays;
    std::unique_ptr<widgets::Nm17xLinePanel> m_panel;
};

void TstNm17xLinePanel::init()
{
    m_bus = new test::ScriptedCanBus;
    m_network = std::make_unique<canopen::CanNetwork>(m_bus);
    m_network->acquire();
    m_network->sdo()->setTimeoutMs(200);
    const QList<std::pair<Variant, canopen::NodeId>> line = { { Variant::Nm172, 3 },
                                                              { Variant::Nm174, 2 } };
    quint32 serial = 0x100;
    for (const auto &[variant, node] : line) {
        auto *d = new SimulatedNm17x(variant, serial++, node);
        connect(m_bus, &test::ScriptedCanBus::frameWritten, d, &SimulatedNm17x::receive);
        connect(d, &SimulatedNm17x::transmit, m_bus,
                [this](const QCanBusFrame &f) { m_bus->feedLater(f); });
        d->start();
        m_displays.append(d);
    }
    m_panel = std::make_unique<widgets::Nm17xLinePanel>();
    m_panel->setNetwork(m_network.get());
    m_panel->show();
}

void TstNm17xLinePanel::cleanup()
{
    m_panel.reset();
    qDeleteAll(m_displays);
    m_displays.clear();
    m_network.reset();
}

void TstNm17xLinePanel::findsTheDisplays()
{
    QTest::mouseClick(button("find"), Qt::LeftButton);
    QTRY_COMPARE(m_panel->model()->rowCount(), 2);
    QCOMPARE(cell(0, widgets::Nm17xLineModel::Node), QStringLiteral("2"));
    QCOMPARE(cell(0, widgets::Nm17xLineModel::Variant), QStringLiteral("NM174"));
    QCOMPARE(cell(1, widgets::Nm17xLineModel::Serial), QStringLiteral("0x00000100"));
    QCOMPARE(m_panel->selectedNode(), canopen::NodeId(2));
    QVERIFY(m_panel->message().contains(QLatin1String("2 display")));
}

void TstNm17xLinePanel::setpointWithReleaseReachesInPosition()
{
    QTest::mouseClick(button("find"), Qt::LeftButton);
    QTRY_COMPARE(m_panel->model()->rowCount(), 2);
    m_panel->selectNode(3);
    m_panel->findChild<QDoubleSpinBox *>("setpoint")->setValue(12.5);
    m_panel->findChild<QComboBox *>("kind")->setCurrentIndex(1); // with release
    QTest::mouseClick(button("send"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(
        cell(1, widgets::Nm17xLineModel::Status).contains(QLatin1String("In Position")), 10000);
    QCOMPARE(cell(1, widgets::Nm17xLineModel::Position), QStringLiteral("12.50 mm"));
    QCOMPARE(cell(1, widgets::Nm17xLineModel::Setpoint), QStringLiteral("12.50 mm"));
    QCOMPARE(m_displays.at(0)->position(), 1250);
}

void TstNm17xLinePanel::jogAndStop()
{
    QTest::mouseClick(button("find"), Qt::LeftButton);
    QTRY_COMPARE(m_panel->model()->rowCount(), 2);
    m_panel->selectNode(2);
    m_panel->findChild<QComboBox *>("speed")->setCurrentIndex(2); // fast
    QTest::mouseClick(button("jogLeft"), Qt::LeftButton);
    QTRY_VERIFY(m_displays.at(1)->position() < -300);
    QTRY_VERIFY(cell(0, widgets::Nm17xLineModel::Status).contains(QLatin1String("Moving")));
    QVERIFY(cell(0, widgets::Nm17xLineModel::Status).endsWith(QLatin1String("(left)")));
    QTest::mouseClick(button("stop"), Qt::LeftButton);
    QTRY_VERIFY(!m_displays.at(1)->spindle().isMoving());
    QTRY_COMPARE(cell(0, widgets::Nm17xLineModel::Position),
                 formatPosition(m_displays.at(1)->position(), false));
}

void TstNm17xLinePanel::broadcastsReachEveryDisplay()
{
    m_panel->findChild<QDoubleSpinBox *>("preset")->setValue(250);
    QTest::mouseClick(button("presetAll"), Qt::LeftButton);
    QTRY_COMPARE(m_displays.at(0)->position(), 25000);
    QTRY_COMPARE(m_displays.at(1)->position(), 25000);
    auto *unit = m_panel->findChild<QComboBox *>("unit");
    unit->setCurrentIndex(1);
    Q_EMIT unit->activated(1);
    QTRY_COMPARE(m_displays.at(0)->read({ 0x2001, 0 }).value().toUInt(), 1u);
    QCOMPARE(m_displays.at(1)->read({ 0x2001, 0 }).value().toUInt(), 1u);
    QVERIFY(m_panel->message().contains(QLatin1String("inch")));
}

// The CAN monitor of a connection to node 2 shows the TxPDO2 of node 3, too, field by field with
// names and units, once the line has found the displays (each is described to the network).
void TstNm17xLinePanel::canMonitorNamesThePdoFieldsOfTheLine()
{
    const auto uri = ConnectionUri::parse(QStringLiteral("canopen+slcan://127.0.0.1:1?node=2"));
    QVERIFY(uri.ok());
    canopen::CanopenConnection connection(
        *uri, std::shared_ptr<canopen::CanNetwork>(m_network.get(), [](canopen::CanNetwork *) {}));
    widgets::CanMonitor monitor;
    monitor.setConnection(&connection);
    const auto decodedTexts = [&monitor](quint32 id) {
        QStringList texts;
        const QAbstractItemModel *model = monitor.model();
        for (int row = 0; row < model->rowCount(); ++row) {
            if (model->index(row, widgets::CanMonitorModel::Id)
                    .data()
                    .toString()
                    .toUInt(nullptr, 16)
                == id)
                texts.append(
                    model->index(row, widgets::CanMonitorModel::Decoded).data().toString());
        }
        return texts;
    };

    QTest::mouseClick(button("find"), Qt::LeftButton);
    QTRY_COMPARE(m_panel->model()->rowCount(), 2);
    m_panel->selectNode(3);
    m_panel->findChild<QDoubleSpinBox *>("setpoint")->setValue(2.5);
    m_panel->findChild<QComboBox *>("kind")->setCurrentIndex(1); // with release
    QTest::mouseClick(button("send"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!decodedTexts(0x283).isEmpty(), 10000);
    const QString text = decodedTexts(0x283).constLast();
    QVERIFY2(text.contains(QLatin1String("Position value = ")), qPrintable(text));
    QVERIFY2(text.contains(QLatin1String("1/100 mm")), qPrintable(text));
    QVERIFY2(text.contains(QLatin1String("Device status")), qPrintable(text));
}

// Three displays as delivered (node 127): the dialog offers 2, 3, 4; the test turns the shaft of
// the display that should take each (in the order 2nd, 3rd, 1st); at the end all restart with
// their new ids.
void TstNm17xLinePanel::guidedAddressingAlongTheLine()
{
    m_panel->setNetwork(nullptr);
    qDeleteAll(m_displays);
    m_displays.clear();
    for (quint32 serial : { 0x200u, 0x201u, 0x202u }) {
        auto *d =
            new SimulatedNm17x(serial == 0x202u ? Variant::Nm174 : Variant::Nm172, serial, 127);
        connect(m_bus, &test::ScriptedCanBus::frameWritten, d, &SimulatedNm17x::receive);
        connect(d, &SimulatedNm17x::transmit, m_bus,
                [this](const QCanBusFrame &f) { m_bus->feedLater(f); });
        d->start();
        m_displays.append(d);
    }
    m_panel->setNetwork(m_network.get());
    widgets::Nm17xAddressingDialog *dialog = m_panel->openAddressing();
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    dialog->findChild<QSpinBox *>("firstNode")->setValue(2);
    dialog->findChild<QSpinBox *>("count")->setValue(3);
    const QList<int> order = { 1, 2, 0 }; // which display takes 2, 3, 4
    QTest::mouseClick(dialog->findChild<QPushButton *>("start"), Qt::LeftButton);
    for (int step = 0; step < 3; ++step) {
        const int node = 2 + step;
        QTRY_VERIFY(dialog->instruction().contains(QStringLiteral("node %1").arg(node)));
        QVERIFY(dialog->isRunning());
        QTRY_COMPARE(int(m_displays.at(order[step])->offeredNodeId()), node);
        const QString dir = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT_DIR");
        if (step == 1 && !dir.isEmpty())
            dialog->grab().save(dir + QStringLiteral("/screenshot-nm17x-addressing.png"));
        m_displays.at(order[step])->turnShaft(5);
        QTRY_COMPARE(dialog->findChild<QProgressBar *>("progress")->value(), step + 1);
    }
    QTRY_VERIFY(!dialog->isRunning());
    QCOMPARE(dialog->assignedIds(), (QList<canopen::NodeId> { 2, 3, 4 }));
    QCOMPARE(dialog->steps().size(), 3);
    QVERIFY2(dialog->instruction().contains(QLatin1String("addressed: node 2, 3, 4")),
             qPrintable(dialog->instruction()));
    QTRY_COMPARE(int(m_displays.at(1)->nodeId()), 2);
    QTRY_COMPARE(int(m_displays.at(2)->nodeId()), 3);
    QTRY_COMPARE(int(m_displays.at(0)->nodeId()), 4);
    QTest::mouseClick(dialog->findChild<QPushButton *>("cancel"), Qt::LeftButton); // "Close"
}

// No display answers the second offer within its time: the dialog names that step's error and
// keeps the id assigned before.
void TstNm17xLinePanel::guidedAddressingTimeoutIsNamedPerStep()
{
    widgets::Nm17xAddressingDialog dialog(m_network.get());
    dialog.setFirstNode(10);
    dialog.setCount(2);
    dialog.setStepSeconds(1);
    dialog.show();
    for (SimulatedNm17x *d : std::as_const(m_displays))
        QVERIFY(!d->inAddressingMode());
    dialog.start();
    QTRY_VERIFY(dialog.instruction().contains(QLatin1String("node 10")));
    QTRY_VERIFY(m_displays.at(0)->inAddressingMode());
    m_displays.at(0)->turnShaft(5);
    QTRY_VERIFY(dialog.instruction().contains(QLatin1String("node 11")));
    QTRY_VERIFY_WITH_TIMEOUT(!dialog.isRunning(), 5000);
    QCOMPARE(dialog.assignedIds(), QList<canopen::NodeId> { 10 });
    const QStringList steps = dialog.steps();
    QCOMPARE(steps.size(), 2);
    QVERIFY2(steps.at(0).startsWith(QLatin1String("node 10: taken")), qPrintable(steps.at(0)));
    QVERIFY2(steps.at(1).startsWith(QLatin1String("node 11: ")), qPrintable(steps.at(1)));
    QVERIFY(dialog.instruction().contains(QLatin1String("node 10")));
}

void TstNm17xLinePanel::withoutNetworkNothingIsEnabled()
{
    m_panel->setNetwork(nullptr);
    QVERIFY(!button("find")->isEnabled());
    QVERIFY(!button("send")->isEnabled());
    QVERIFY(!button("stopAll")->isEnabled());
    QCOMPARE(m_panel->model()->rowCount(), 0);
}

// Input mode, key mode and oscillation of the selected display from the dock: the combo boxes
// show what the display has, and a choice is written to it.
void TstNm17xLinePanel::modesOfTheSelectedDisplay()
{
    QTest::mouseClick(button("find"), Qt::LeftButton);
    QTRY_COMPARE(m_panel->model()->rowCount(), 2);
    SimulatedNm17x *nm172 = m_displays.at(0);
    QVERIFY(nm172->write({ 0x2041, 4 }, 2u).ok()); // the display has "Middle" before
    m_panel->selectNode(3);
    widgets::Nm17xSettingsBox *box = m_panel->settingsBox();
    QCOMPARE(box->node(), canopen::NodeId(3));
    auto *inputs = box->findChild<QComboBox *>("inputMode");
    auto *keys = box->findChild<QComboBox *>("keyMode");
    QTRY_COMPARE(keys->currentData().toInt(), 2);
    QCOMPARE(inputs->currentText(), QStringLiteral("Standard / Oscillating"));

    QTest::mouseClick(box->findChild<QPushButton *>("oscillate"), Qt::LeftButton);
    QTRY_VERIFY(nm172->isOscillating());
    QTRY_VERIFY(m_panel->message().contains(QLatin1String("oscillating")));
    QVERIFY(nm172->statusWord() & status::Oscillating);
    QTest::mouseClick(box->findChild<QPushButton *>("stopOscillating"), Qt::LeftButton);
    QTRY_VERIFY(!nm172->isOscillating());

    const int takten = inputs->findData(1);
    inputs->setCurrentIndex(takten);
    Q_EMIT inputs->activated(takten);
    QTRY_COMPARE(nm172->read({ 0x2041, 3 }).value().toUInt(), 1u);
    QTRY_VERIFY2(m_panel->message().contains(QLatin1String("Takten")),
                 qPrintable(m_panel->message()));
    const int fast = keys->findData(3);
    keys->setCurrentIndex(fast);
    Q_EMIT keys->activated(fast);
    QTRY_COMPARE(nm172->read({ 0x2041, 4 }).value().toUInt(), 3u);
    // In Takten, input F positions to D1.
    QVERIFY(nm172->write({ 0x2045, 1 }, 1500).ok());
    QTRY_COMPARE(nm172->read({ 0x2045, 1 }).value().toInt(), 1500);
    nm172->setInputs(true, false);
    QTRY_VERIFY_WITH_TIMEOUT(nm172->statusWord() & status::InPosition, 10000);
    QCOMPARE(nm172->position(), 1500);

    // Selecting the other display shows its own values.
    m_panel->selectNode(2);
    QCOMPARE(keys->currentIndex(), -1); // not the previous display's value while reading
    QTRY_COMPARE(inputs->currentData().toInt(), 0);
    QTRY_COMPARE(keys->currentData().toInt(), 0);
}

// Scaling from the pitch, the jump filter and the dynamic pre-shutdown, written to the selected
// display and read back.
void TstNm17xLinePanel::settingsOfTheSelectedDisplay()
{
    QTest::mouseClick(button("find"), Qt::LeftButton);
    QTRY_COMPARE(m_panel->model()->rowCount(), 2);
    m_panel->selectNode(3);
    widgets::Nm17xSettingsBox *box = m_panel->settingsBox();
    auto *scaling = box->findChild<QLabel *>("scaling");
    QTRY_COMPARE(scaling->text(), QStringLiteral("1736111 = 4.00 mm/rev"));
    QCOMPARE(box->findChild<QSpinBox *>("filterWidth")->value(), 100);
    QTRY_COMPARE(box->findChild<QSpinBox *>("filterCount")->value(), 5); // NM174's is 2

    box->findChild<QDoubleSpinBox *>("pitch")->setValue(8.0);
    QTest::mouseClick(box->findChild<QPushButton *>("setScaling"), Qt::LeftButton);
    QTRY_COMPARE(m_displays.at(0)->read({ 0x2004, 0 }).value().toUInt(), 3472222u);
    QTRY_COMPARE(scaling->text(), QStringLiteral("3472222 = 8.00 mm/rev"));

    box->findChild<QSpinBox *>("filterWidth")->setValue(40);
    box->findChild<QSpinBox *>("filterCount")->setValue(3);
    QTest::mouseClick(box->findChild<QPushButton *>("setFilter"), Qt::LeftButton);
    QTRY_COMPARE(m_displays.at(0)->read({ 0x2005, 1 }).value().toUInt(), 40u);
    QTRY_COMPARE(m_displays.at(0)->read({ 0x2005, 2 }).value().toUInt(), 3u);

    auto *preShutdown = box->findChild<QCheckBox *>("preShutdown");
    QVERIFY(!preShutdown->isChecked());
    QTest::mouseClick(preShutdown, Qt::LeftButton);
    QTRY_COMPARE(m_displays.at(0)->read({ 0x2041, 2 }).value().toUInt(), 1u);
    QTRY_VERIFY(box->switchOffText().contains(QLatin1String("0.00 mm")));
}

// Selecting another display never shows the previous one's settings: each field is blank and
// its command disabled until this display's value has come; a field whose read failed stays
// blank, and its command asks for a value instead of writing the hidden previous one.
void TstNm17xLinePanel::settingsOfAnotherDisplayAreBlankUntilRead()
{
    // With DRIVEBENCH_SCREENSHOT_DIR: how the box looks while the display's values are read,
    // and once a display did not answer (nm17x-settings-loading.png, -noanswer.png).
    const QString shots = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT_DIR");
    if (!shots.isEmpty())
        m_panel->resize(1000, 720);
    QTest::mouseClick(button("find"), Qt::LeftButton);
    QTRY_COMPARE(m_panel->model()->rowCount(), 2);
    QVERIFY(m_displays.at(0)->write({ 0x2041, 2 }, 1u).ok()); // NM172: pre-shutdown on
    m_panel->selectNode(3);
    widgets::Nm17xSettingsBox *box = m_panel->settingsBox();
    auto *width = box->findChild<QSpinBox *>("filterWidth");
    auto *count = box->findChild<QSpinBox *>("filterCount");
    auto *pitch = box->findChild<QDoubleSpinBox *>("pitch");
    auto *preShutdown = box->findChild<QCheckBox *>("preShutdown");
    auto *setFilter = box->findChild<QPushButton *>("setFilter");
    QTRY_COMPARE(count->value(), 5);
    QTRY_VERIFY(preShutdown->isEnabled());
    QCOMPARE(preShutdown->checkState(), Qt::Checked);
    QCOMPARE(width->cleanText(), QStringLiteral("100"));
    QVERIFY(setFilter->isEnabled());

    m_panel->selectNode(2);
    QVERIFY(width->cleanText().isEmpty());
    QVERIFY(count->cleanText().isEmpty());
    QVERIFY(pitch->cleanText().isEmpty());
    QCOMPARE(preShutdown->checkState(), Qt::PartiallyChecked);
    QVERIFY(!preShutdown->isEnabled());
    QVERIFY(!setFilter->isEnabled());
    if (!shots.isEmpty())
        QVERIFY(m_panel->grab().save(shots + QStringLiteral("/nm17x-settings-loading.png")));
    QTRY_COMPARE(count->cleanText(), QStringLiteral("2"));
    QTRY_COMPARE(width->cleanText(), QStringLiteral("100")); // the same value as before
    QTRY_COMPARE(preShutdown->checkState(), Qt::Unchecked);
    QVERIFY(preShutdown->isEnabled());
    QVERIFY(setFilter->isEnabled());
    QVERIFY(!pitch->cleanText().isEmpty());

    // A display that stops answering: the fields stay blank, and Set filter asks for values.
    SimulatedNm17x *nm172 = m_displays.at(0);
    disconnect(m_bus, &test::ScriptedCanBus::frameWritten, nm172, &SimulatedNm17x::receive);
    m_panel->selectNode(3);
    QTRY_VERIFY_WITH_TIMEOUT(setFilter->isEnabled(), 5000);
    QVERIFY(width->cleanText().isEmpty());
    QVERIFY(count->cleanText().isEmpty());
    const quint32 before = nm172->read({ 0x2005, 1 }).value().toUInt();
    QTest::mouseClick(setFilter, Qt::LeftButton);
    QVERIFY2(m_panel->message().contains(QLatin1String("Enter the jump filter")),
             qPrintable(m_panel->message()));
    QCOMPARE(nm172->read({ 0x2005, 1 }).value().toUInt(), before);
    if (!shots.isEmpty())
        QVERIFY(m_panel->grab().save(shots + QStringLiteral("/nm17x-settings-noanswer.png")));
}

// A display at 250 kbit/s while the line's bus runs at 125: the scan names where it answers.
void TstNm17xLinePanel::scanFindsTheDisplaysAtTheirBitrate()
{
    nm17x::Nm17xSim sim;
    sim.create({ { Variant::Nm172, 5 } });
    sim.setBitrate(250000);
    QVERIFY(sim.startSlcan(0).ok());
    QVERIFY(!button("scanBitrates")->isEnabled()); // no bus URI yet
    const auto uri = ConnectionUri::parse(
        QStringLiteral("canopen+slcan://127.0.0.1:%1?bitrate=125000").arg(sim.slcanPort()));
    QVERIFY(uri.ok());
    m_panel->setBusUri(*uri);
    QVERIFY(button("scanBitrates")->isEnabled());
    QTest::mouseClick(button("scanBitrates"), Qt::LeftButton);
    QVERIFY(m_panel->isScanning());
    QTRY_VERIFY_WITH_TIMEOUT(!m_panel->isScanning(), 20000);
    QVERIFY2(m_panel->message().contains(QLatin1String("125 kbit/s: no display")),
             qPrintable(m_panel->message()));
    QVERIFY2(m_panel->message().contains(QLatin1String("250 kbit/s: node 5")),
             qPrintable(m_panel->message()));
}

bool TstNm17xLinePanel::sendToABlockedShaft(SimulatedNm17x **nm172)
{
    QTest::mouseClick(button("find"), Qt::LeftButton);
    if (!QTest::qWaitFor([this] { return m_panel->model()->rowCount() == 2; }))
        return false;
    *nm172 = m_displays.at(0);
    if (!(*nm172)->write({ 0x2047, 2 }, 3u).ok()) // following error after 0.3 s
        return false;
    (*nm172)->spindle().setShaftBlocked(true);
    m_panel->selectNode(3);
    m_panel->findChild<QDoubleSpinBox *>("setpoint")->setValue(5);
    m_panel->findChild<QComboBox *>("kind")->setCurrentIndex(1); // with release
    QTest::mouseClick(button("send"), Qt::LeftButton);
    return true;
}

// TxPDO2 shows only the error bit: the panel reads the error word and names Er 3 and Er 6, with
// the remedy in the tool tip.
void TstNm17xLinePanel::displayErrorsAreNamed()
{
    SimulatedNm17x *nm172 = nullptr;
    QVERIFY(sendToABlockedShaft(&nm172));
    const QModelIndex errors = m_panel->model()->index(1, widgets::Nm17xLineModel::Errors);
    QTRY_VERIFY2_WITH_TIMEOUT(errors.data().toString().startsWith(QLatin1String("Er 3 (shaft")),
                              qPrintable(errors.data().toString()), 5000);
    QVERIFY(cell(1, widgets::Nm17xLineModel::Status).contains(QLatin1String("Error")));
    QVERIFY2(errors.data(Qt::ToolTipRole).toString().contains(QLatin1String("mechanics")),
             qPrintable(errors.data(Qt::ToolTipRole).toString()));

    nm172->spindle().setShaftBlocked(false);
    nm172->spindle().setWiringReversed(true);
    QTest::mouseClick(button("send"), Qt::LeftButton);
    QTRY_VERIFY2_WITH_TIMEOUT(errors.data().toString().startsWith(QLatin1String("Er 6 (direction")),
                              qPrintable(errors.data().toString()), 5000);

    nm172->spindle().setWiringReversed(false);
    QTest::mouseClick(button("send"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(
        cell(1, widgets::Nm17xLineModel::Status).contains(QLatin1String("In Position")), 10000);
    QCOMPARE(cell(1, widgets::Nm17xLineModel::Errors), QStringLiteral("-"));
}

// The status says "error" but the error word cannot be read (the display stopped answering
// SDOs): the Errors column says that, never "-" (no error), and names the cause in its tool tip.
void TstNm17xLinePanel::unreadableErrorWordIsNotShownAsNoError()
{
    SimulatedNm17x *nm172 = nullptr;
    QVERIFY(sendToABlockedShaft(&nm172));
    // From here on the display hears nothing, but goes on sending its PDOs.
    QVERIFY(
        disconnect(m_bus, &test::ScriptedCanBus::frameWritten, nm172, &SimulatedNm17x::receive));
    const QModelIndex errors = m_panel->model()->index(1, widgets::Nm17xLineModel::Errors);
    QTRY_COMPARE_WITH_TIMEOUT(errors.data().toString(), QStringLiteral("error (reading its code…)"),
                              5000);
    QVERIFY(cell(1, widgets::Nm17xLineModel::Status).contains(QLatin1String("Error")));
    QTRY_COMPARE_WITH_TIMEOUT(errors.data().toString(),
                              QStringLiteral("error (its code could not be read)"), 5000);
    const QString tip = errors.data(Qt::ToolTipRole).toString();
    QVERIFY2(tip.contains(QLatin1String("204Eh:02")) && tip.contains(QLatin1String("timeout")),
             qPrintable(tip));
    // With DRIVEBENCH_SCREENSHOT_DIR: the table in this state (nm17x-errors-unread.png).
    const QString shots = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT_DIR");
    if (!shots.isEmpty()) {
        m_panel->resize(1000, 720);
        m_panel->grab().save(shots + QStringLiteral("/nm17x-errors-unread.png"));
    }
    // It stays so while it is read again (no flicker back to "reading" on every TxPDO2).
    for (int i = 0; i < 6; ++i) {
        QTest::qWait(250);
        QCOMPARE(errors.data().toString(), QStringLiteral("error (its code could not be read)"));
    }
    // The display answers again: its error is named at the next try.
    connect(m_bus, &test::ScriptedCanBus::frameWritten, nm172, &SimulatedNm17x::receive);
    QTRY_VERIFY2_WITH_TIMEOUT(errors.data().toString().startsWith(QLatin1String("Er 3 (shaft")),
                              qPrintable(errors.data().toString()), 5000);
}

// An NM170 (no motor): scaling and jump filter can be set, the modes and the pre-shutdown cannot.
void TstNm17xLinePanel::nm170HasNoMotorSettings()
{
    nm17x::Nm17xLine line(m_network.get());
    widgets::Nm17xSettingsBox box;
    box.setDisplay(&line, 9, Variant::Nm170);
    QVERIFY(!box.findChild<QComboBox *>("inputMode")->isEnabled());
    QVERIFY(!box.findChild<QPushButton *>("oscillate")->isEnabled());
    QVERIFY(!box.findChild<QCheckBox *>("preShutdown")->isEnabled());
    // Nothing answers at node 9: once its reads have failed, the values can be entered.
    QTRY_VERIFY(box.findChild<QPushButton *>("setScaling")->isEnabled());
    QTRY_VERIFY(box.findChild<QPushButton *>("setFilter")->isEnabled());
    box.setDisplay(&line, 9, Variant::Nm172);
    QVERIFY(box.findChild<QComboBox *>("inputMode")->isEnabled());
    box.setDisplay(nullptr, 0, Variant::Nm172);
    QVERIFY(!box.findChild<QPushButton *>("setScaling")->isEnabled());
}

// For the README: DRIVEBENCH_SCREENSHOT_DIR=docs writes screenshot-nm17x.png of the panel
// while one display positions and another jogs.
void TstNm17xLinePanel::screenshotOfARunningLine()
{
    const QString dir = qEnvironmentVariable("DRIVEBENCH_SCREENSHOT_DIR");
    if (dir.isEmpty())
        QSKIP("DRIVEBENCH_SCREENSHOT_DIR not set");
    m_panel->resize(980, 300);
    QTest::mouseClick(button("find"), Qt::LeftButton);
    QTRY_COMPARE(m_panel->model()->rowCount(), 2);
    m_panel->selectNode(2);
    m_panel->findChild<QComboBox *>("speed")->setCurrentIndex(1);
    QTest::mouseClick(button("jogRight"), Qt::LeftButton);
    m_panel->selectNode(3);
    m_panel->findChild<QDoubleSpinBox *>("setpoint")->setValue(125.5);
    m_panel->findChild<QComboBox *>("kind")->setCurrentIndex(1);
    QTest::mouseClick(button("send"), Qt::LeftButton);
    QTRY_VERIFY(m_displays.at(0)->position() > 3000 && m_displays.at(1)->position() > 1000);
    QTRY_VERIFY(cell(1, widgets::Nm17xLineModel::Status).contains(QLatin1String("Moving")));
    QVERIFY(m_panel->grab().save(dir + QStringLiteral("/screenshot-nm17x.png")));
}

QTEST_MAIN(TstNm17xLinePanel)
#include "tst_nm17xlinepanel.moc"
