#include "fakeconnection.h"
#include "widgets/connection/connectiondialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTest>

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
    return registry;
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
        QCOMPARE(protocol->count(), 2);
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
