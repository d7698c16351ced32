#include "fakeconnection.h"
#include "widgets/connection/connectiondialog.h"

#include <QCanBus>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMimeData>
#include <QPushButton>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QUrl>

using namespace db;
using db::widgets::ConnectionDialog;

namespace {
// How often a plan was prepared (the description loaded).
int g_prepared = 0;

ProtocolRegistry testRegistry()
{
    ProtocolRegistry registry;
    const auto makeFake =
        [](const ConnectionPlan &plan) -> Result<std::unique_ptr<DeviceConnection>> {
        return std::unique_ptr<DeviceConnection>(
            std::make_unique<test::FakeConnection>(plan.uri.toString()));
    };
    registry.add({ QStringLiteral("refgo"),
                   QStringLiteral("refgo"),
                   QStringLiteral("MovingCap RefGo (ASCII over TCP)"),
                   QStringLiteral("refgo://HOST[:PORT]"),
                   10001,
                   makeFake,
                   {},
                   {} });
    registry.add({ QStringLiteral("canopen+socketcan"),
                   QStringLiteral("canopen"),
                   QStringLiteral("CANopen over SocketCAN"),
                   QStringLiteral("canopen+socketcan://IFACE?node=N&bitrate=B"),
                   -1,
                   makeFake,
                   {},
                   [](ConnectionPlan &plan) -> Result<void> {
                       ++g_prepared;
                       const QString eds = plan.uri.queryValue(QStringLiteral("eds"));
                       if (!eds.isEmpty())
                           return Error(Error::Kind::InvalidArgument,
                                        QStringLiteral("eds=%1: cannot open the file").arg(eds));
                       return {};
                   } });
    // CANopen over a Qt CAN plugin and over SLCAN, as the application registers them.
    for (const QString &transport : { QStringLiteral("virtualcan"), QStringLiteral("slcan") }) {
        const bool slcan = transport == QLatin1String("slcan");
        registry.add({ QStringLiteral("canopen+") + transport,
                       QStringLiteral("canopen"),
                       QStringLiteral("CANopen over ") + transport,
                       QStringLiteral("canopen+%1://HOST?node=N").arg(transport),
                       slcan ? 15001 : -1,
                       makeFake,
                       {},
                       {} });
    }
    return registry;
}

QString labelOf(ConnectionDialog &dialog, QWidget *field)
{
    auto *form = dialog.findChild<QFormLayout *>();
    auto *label = form ? qobject_cast<QLabel *>(form->labelForField(field)) : nullptr;
    return label ? label->text() : QString();
}
} // namespace

class TestConnectionDialog : public QObject
{
    Q_OBJECT

private:
    const ProtocolRegistry m_registry = testRegistry();

    static QPushButton *okButton(ConnectionDialog &dialog)
    {
        return dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
    }

private Q_SLOTS:
    void listsTheRegisteredProtocols()
    {
        ConnectionDialog dialog(m_registry, {});
        auto *protocol = dialog.findChild<QComboBox *>(QStringLiteral("protocol"));
        QCOMPARE(protocol->count(), 4);
        QCOMPARE(protocol->itemText(0), QStringLiteral("MovingCap RefGo (ASCII over TCP)"));
        QVERIFY(!okButton(dialog)->isEnabled());
    }

    void fieldsBuildTheUriWithDefaultPort()
    {
        ConnectionDialog dialog(m_registry, {});
        dialog.show();
        auto *port = dialog.findChild<QSpinBox *>(QStringLiteral("port"));
        QCOMPARE(port->value(), 10001);
        QTest::keyClicks(dialog.findChild<QLineEdit *>(QStringLiteral("host")),
                         QStringLiteral("192.168.2.150"));
        QVERIFY(dialog.isValid());
        QCOMPARE(dialog.uri(), QStringLiteral("refgo://192.168.2.150:10001"));
        QVERIFY(okButton(dialog)->isEnabled());
        port->setValue(10002);
        QCOMPARE(dialog.uri(), QStringLiteral("refgo://192.168.2.150:10002"));
    }

    void freeUriGetsDefaultPortAndFillsFields()
    {
        ConnectionDialog dialog(m_registry, {});
        dialog.setUri(QStringLiteral("refgo://10.0.0.7"));
        QCOMPARE(dialog.uri(), QStringLiteral("refgo://10.0.0.7:10001"));
        QCOMPARE(dialog.findChild<QLineEdit *>(QStringLiteral("host"))->text(),
                 QStringLiteral("10.0.0.7"));
    }

    void anAddressWithoutPortShowsTheProtocolsPort()
    {
        // The Morse panel's Connect gives "refgo://IP": after a recent connection on another
        // port, the field shows the port the connection will use, and so does an SLCAN one.
        ConnectionDialog dialog(m_registry, { QStringLiteral("refgo://127.0.0.1:40123") });
        auto *port = dialog.findChild<QSpinBox *>(QStringLiteral("port"));
        QCOMPARE(port->value(), 40123);
        dialog.setUri(QStringLiteral("refgo://10.20.30.40"));
        QCOMPARE(port->value(), 10001);
        QCOMPARE(dialog.uri(), QStringLiteral("refgo://10.20.30.40:10001"));
        dialog.setUri(QStringLiteral("canopen+slcan://127.0.0.1:40999?node=50"));
        QCOMPARE(port->value(), 40999);
        dialog.setUri(QStringLiteral("canopen+slcan://10.20.30.40?node=50"));
        QCOMPARE(port->value(), 15001);
        QCOMPARE(dialog.uri(), QStringLiteral("canopen+slcan://10.20.30.40:15001?node=50"));
        // Editing the host keeps the port the field shows.
        QLineEdit *host = dialog.findChild<QLineEdit *>(QStringLiteral("host"));
        host->clear();
        QTest::keyClicks(host, QStringLiteral("10.20.30.41"));
        QCOMPARE(dialog.uri(), QStringLiteral("canopen+slcan://10.20.30.41:15001?node=50"));
    }

    void portlessProtocolWithOptions()
    {
        ConnectionDialog dialog(m_registry, {});
        dialog.show();
        dialog.findChild<QComboBox *>(QStringLiteral("protocol"))->setCurrentIndex(1);
        QVERIFY(!dialog.findChild<QSpinBox *>(QStringLiteral("port"))->isEnabled());
        QTest::keyClicks(dialog.findChild<QLineEdit *>(QStringLiteral("host")),
                         QStringLiteral("can0"));
        QTest::keyClicks(dialog.findChild<QLineEdit *>(QStringLiteral("options")),
                         QStringLiteral("node=50"));
        QCOMPARE(dialog.uri(), QStringLiteral("canopen+socketcan://can0?node=50"));
    }

    void okPreparesThePlanOnceAndStaysOpenWithTheCause()
    {
        ConnectionDialog dialog(m_registry, {});
        dialog.show();
        g_prepared = 0;
        QTest::keyClicks(dialog.findChild<QLineEdit *>(QStringLiteral("uri")),
                         QStringLiteral("canopen+socketcan://can0?node=5&eds=/nonexistent/n.eds"));
        QVERIFY(dialog.isValid()); // the cheap check passes while typing
        QCOMPARE(g_prepared, 0); // nothing is loaded per keystroke
        QTest::mouseClick(okButton(dialog), Qt::LeftButton);
        QCOMPARE(g_prepared, 1);
        QVERIFY(dialog.isVisible()); // stays open with the cause
        QVERIFY2(dialog.errorText().contains(QStringLiteral("/nonexistent/n.eds")),
                 qPrintable(dialog.errorText()));
        QVERIFY(!dialog.findChild<QSpinBox *>(QStringLiteral("port"))->isVisible());
        QCoreApplication::processEvents(); // the form takes the new label widths
        if (const QByteArray shots = qgetenv("DRIVEBENCH_SCREENSHOT_DIR"); !shots.isEmpty())
            dialog.grab().save(QString::fromLocal8Bit(shots)
                               + QStringLiteral("/connect-error.png"));
        dialog.setUri(QStringLiteral("canopen+socketcan://can0?node=5"));
        QTest::mouseClick(okButton(dialog), Qt::LeftButton);
        QCOMPARE(g_prepared, 2);
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        QCOMPARE(dialog.plan().uri.toString(), QStringLiteral("canopen+socketcan://can0?node=5"));
    }

    void invalidUriDisablesOkAndExplains_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown scheme") << "vabus://10.0.0.1"
                                        << "unknown protocol 'vabus'";
        QTest::newRow("no scheme") << "10.0.0.1"
                                   << "is not a connection URI";
        QTest::newRow("port too big") << "refgo://10.0.0.1:70000"
                                      << "";
    }

    void invalidUriDisablesOkAndExplains()
    {
        QFETCH(QString, text);
        QFETCH(QString, message);
        ConnectionDialog dialog(m_registry, {});
        dialog.setUri(text);
        QVERIFY(!dialog.isValid());
        QVERIFY(dialog.uri().isEmpty());
        QVERIFY(!okButton(dialog)->isEnabled());
        QVERIFY(!dialog.errorText().isEmpty());
        QVERIFY2(dialog.errorText().contains(message), qPrintable(dialog.errorText()));
    }

    void recentConnectionsArePickedAndReturned()
    {
        const QStringList recent { QStringLiteral("refgo://10.0.0.1:10001"),
                                   QStringLiteral("refgo://10.0.0.2:10001") };
        ConnectionDialog dialog(m_registry, recent);
        QCOMPARE(dialog.uri(), recent.first()); // the newest is preselected
        dialog.setUri(QStringLiteral("refgo://10.0.0.2"));
        QCOMPARE(dialog.recentUris(),
                 (QStringList { QStringLiteral("refgo://10.0.0.2:10001"),
                                QStringLiteral("refgo://10.0.0.1:10001") }));
    }

    void canPluginOffersItsInterfacesAndBitrates()
    {
        const QList<QCanBusDeviceInfo> devices =
            QCanBus::instance()->availableDevices(QStringLiteral("virtualcan"));
        if (devices.isEmpty())
            QSKIP("the Qt virtualcan plugin lists no interface here");
        ConnectionDialog dialog(m_registry, {});
        dialog.show();
        auto *protocol = dialog.findChild<QComboBox *>(QStringLiteral("protocol"));
        auto *hostBox = dialog.findChild<QComboBox *>(QStringLiteral("hostBox"));
        auto *host = dialog.findChild<QLineEdit *>(QStringLiteral("host"));
        auto *node = dialog.findChild<QSpinBox *>(QStringLiteral("node"));
        auto *bitrate = dialog.findChild<QComboBox *>(QStringLiteral("bitrate"));
        QTest::keyClicks(host, QStringLiteral("127.0.0.1")); // typed for RefGo first
        QVERIFY(!node->isVisible()); // RefGo has no node id

        protocol->setCurrentIndex(protocol->findData(QStringLiteral("canopen+virtualcan")));
        QCOMPARE(labelOf(dialog, hostBox), QStringLiteral("&Interface:"));
        QVERIFY(host->text().isEmpty()); // a network address is no CAN interface
        QVERIFY(!dialog.findChild<QSpinBox *>(QStringLiteral("port"))->isEnabled());
        QCOMPARE(hostBox->count(), devices.size());
        for (int i = 0; i < devices.size(); ++i)
            QCOMPARE(hostBox->itemText(i), devices.at(i).name());
        QVERIFY2(host->placeholderText().contains(devices.first().name()),
                 qPrintable(host->placeholderText()));

        // The user picks the first interface, node 5 and 500 kbit/s, without typing a URI.
        hostBox->setFocus();
        QTest::keyClick(hostBox, Qt::Key_Down);
        QCOMPARE(host->text(), devices.first().name());
        QVERIFY(node->isVisible() && bitrate->isVisible());
        node->setValue(5);
        bitrate->setFocus();
        for (int i = 0; i < 3; ++i) // 1000k, 800k, 500k
            QTest::keyClick(bitrate, Qt::Key_Down);
        QCOMPARE(bitrate->currentText(), QStringLiteral("500 kbit/s"));
        QCOMPARE(dialog.uri(),
                 QStringLiteral("canopen+virtualcan://%1?bitrate=500000&node=5")
                     .arg(devices.first().name()));
        QCOMPARE(dialog.findChild<QLineEdit *>(QStringLiteral("options"))->text(),
                 QStringLiteral("node=5&bitrate=500000"));

        QVERIFY(!dialog.findChild<QSpinBox *>(QStringLiteral("port"))->isVisible());
        QCoreApplication::processEvents(); // the form takes the new label widths
        if (const QByteArray shots = qgetenv("DRIVEBENCH_SCREENSHOT_DIR"); !shots.isEmpty())
            dialog.grab().save(QString::fromLocal8Bit(shots) + QStringLiteral("/connect-can.png"));

        // Back to the interface's own bit rate, and a URI fills the fields.
        bitrate->setFocus();
        for (int i = 0; i < 3; ++i)
            QTest::keyClick(bitrate, Qt::Key_Up);
        QCOMPARE(dialog.uri(),
                 QStringLiteral("canopen+virtualcan://%1?node=5").arg(devices.first().name()));
        dialog.setUri(QStringLiteral("canopen+virtualcan://can7?node=12&bitrate=250000"));
        QCOMPARE(node->value(), 12);
        QCOMPARE(bitrate->currentData().toInt(), 250000);
        QCOMPARE(host->text(), QStringLiteral("can7"));
    }

    void slcanAsksForHostAndPort()
    {
        ConnectionDialog dialog(m_registry, {});
        dialog.show();
        auto *protocol = dialog.findChild<QComboBox *>(QStringLiteral("protocol"));
        protocol->setCurrentIndex(protocol->findData(QStringLiteral("canopen+slcan")));
        auto *hostBox = dialog.findChild<QComboBox *>(QStringLiteral("hostBox"));
        QCOMPARE(labelOf(dialog, hostBox), QStringLiteral("&Address:"));
        QCOMPARE(hostBox->count(), 0); // no interface list for a TCP gateway
        auto *port = dialog.findChild<QSpinBox *>(QStringLiteral("port"));
        QVERIFY(port->isEnabled());
        QCOMPARE(port->value(), 15001);
        QVERIFY(dialog.findChild<QComboBox *>(QStringLiteral("bitrate"))
                    ->itemText(0)
                    .contains(QStringLiteral("125")));
        QTest::keyClicks(dialog.findChild<QLineEdit *>(QStringLiteral("host")),
                         QStringLiteral("192.168.0.9"));
        dialog.findChild<QSpinBox *>(QStringLiteral("node"))->setValue(50);
        QCOMPARE(dialog.uri(), QStringLiteral("canopen+slcan://192.168.0.9:15001?node=50"));
    }

    void descriptionIsChosenFromTheLibrary()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString file = dir.filePath(QStringLiteral("drive.eds"));
        {
            QFile f(file);
            QVERIFY(f.open(QIODevice::WriteOnly));
        }
        LibraryEntry fileEntry { QStringLiteral("Drive X"), file, 0x1234, 1, std::nullopt, {} };
        LibraryEntry builtin {
            QStringLiteral("NM172"), QStringLiteral("built-in"), 0xEC, 0x71, std::nullopt, {}
        };
        ConnectionDialog dialog(m_registry, {});
        dialog.setDescriptionEntries({ builtin, fileEntry });
        dialog.show();
        auto *description = dialog.findChild<QComboBox *>(QStringLiteral("description"));
        // Automatic, the library's file, "Other file…"; built-ins come by identity anyway.
        QCOMPARE(description->count(), 3);
        QCOMPARE(description->currentIndex(), 0);
        QCOMPARE(description->itemText(1), QStringLiteral("Drive X (drive.eds)"));
        dialog.setUri(QStringLiteral("canopen+slcan://10.0.0.2?node=3"));
        QCOMPARE(dialog.uri(), QStringLiteral("canopen+slcan://10.0.0.2:15001?node=3"));

        description->setFocus();
        QTest::keyClick(description, Qt::Key_Down);
        QCOMPARE(dialog.uri(),
                 QStringLiteral("canopen+slcan://10.0.0.2:15001?eds=%1&node=3").arg(file));
        QTest::keyClick(description, Qt::Key_Up);
        QCOMPARE(dialog.uri(), QStringLiteral("canopen+slcan://10.0.0.2:15001?node=3"));

        // A description file dropped onto the dialog becomes the URI's description.
        {
            QMimeData data;
            data.setUrls({ QUrl::fromLocalFile(QStringLiteral("/data/dropped.xdd")) });
            QDragEnterEvent enter(QPoint(5, 5), Qt::CopyAction, &data, Qt::LeftButton,
                                  Qt::NoModifier);
            QCoreApplication::sendEvent(&dialog, &enter);
            QVERIFY(enter.isAccepted());
            QDropEvent drop(QPointF(5, 5), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
            QCoreApplication::sendEvent(&dialog, &drop);
        }
        QCOMPARE(dialog.uri(),
                 QStringLiteral("canopen+slcan://10.0.0.2:15001?eds=/data/dropped.xdd&node=3"));
        QCOMPARE(description->currentText(), QStringLiteral("dropped.xdd"));

        // A file named in the URI becomes a choice of its own.
        dialog.setUri(QStringLiteral("canopen+slcan://10.0.0.2?node=3&eds=/data/other.dcf"));
        QCOMPARE(description->currentText(), QStringLiteral("other.dcf"));
        QCOMPARE(description->currentData().toString(), QStringLiteral("/data/other.dcf"));
    }

    void recentListIsBounded()
    {
        QStringList recent;
        for (int i = 0; i < 20; ++i)
            recent = ConnectionDialog::withRecent(recent, QStringLiteral("refgo://h%1").arg(i));
        QCOMPARE(recent.size(), ConnectionDialog::kMaxRecent);
        QCOMPARE(recent.first(), QStringLiteral("refgo://h19"));
        recent = ConnectionDialog::withRecent(recent, QStringLiteral("refgo://h15"));
        QCOMPARE(recent.first(), QStringLiteral("refgo://h15"));
        QCOMPARE(recent.count(QStringLiteral("refgo://h15")), 1);
    }
};

QTEST_MAIN(TestConnectionDialog)
#include "tst_connectiondialog.moc"
