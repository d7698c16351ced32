#include "fakeconnection.h"
#include "resources/builtindescriptions.h"
#include "widgets/odeditor/objectaccessbox.h"

#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

using namespace db;
using db::test::FakeConnection;
using db::widgets::ObjectAccessBox;

class TestObjectAccessBox : public QObject
{
    Q_OBJECT

private:
    std::unique_ptr<FakeConnection> m_fake;
    std::unique_ptr<ObjectAccessBox> m_box;

    QPushButton *button(const char *name) { return m_box->findChild<QPushButton *>(name); }

private Q_SLOTS:
    void init()
    {
        m_fake = std::make_unique<FakeConnection>();
        m_fake->setDictionary(resources::movingCapDictionary());
        m_fake->setValue({ 0x6041, 0 }, QVariant::fromValue<qulonglong>(0x0427));
        m_fake->setValue({ 0x6081, 0 }, QVariant::fromValue<qulonglong>(100));
        m_fake->setValue({ 0x2FFF, 0 }, QVariant::fromValue<qlonglong>(42));
        m_box = std::make_unique<ObjectAccessBox>();
        m_box->setConnection(m_fake.get());
        m_box->show();
        m_fake->open();
        QTRY_VERIFY(m_fake->isConnected());
    }

    void cleanup()
    {
        m_box.reset();
        m_fake.reset();
    }

    void validWriteReachesTheDevice()
    {
        m_box->setAddressText(QStringLiteral("6081:0"));
        QVERIFY(button("write")->isEnabled());
        auto *value = m_box->findChild<QLineEdit *>(QStringLiteral("value"));
        value->clear();
        QTest::keyClicks(value, QStringLiteral("500"));
        QSignalSpy finished(m_box.get(), &ObjectAccessBox::finished);
        QTest::mouseClick(button("write"), Qt::LeftButton);
        QVERIFY(m_box->isBusy());
        QVERIFY(!button("write")->isEnabled()); // one request at a time
        QTRY_COMPARE(finished.count(), 1);
        QCOMPARE(finished.first().first().toBool(), true);
        QCOMPARE(m_fake->writes.size(), 1);
        QCOMPARE(m_fake->writes.first().first, ObjectAddress(0x6081, 0));
        QCOMPARE(m_fake->value({ 0x6081, 0 }).toULongLong(), 500ull);
        QVERIFY(m_box->resultText().contains(QStringLiteral("500 units/s")));
    }

    void readShowsValueInDecimalAndHex()
    {
        m_box->setAddressText(QStringLiteral("6041:0"));
        QSignalSpy finished(m_box.get(), &ObjectAccessBox::finished);
        QTest::mouseClick(button("read"), Qt::LeftButton);
        QTRY_COMPARE(finished.count(), 1);
        QCOMPARE(m_box->valueText(), QStringLiteral("1063"));
        m_box->setHex(true);
        QCOMPARE(m_box->valueText(), QStringLiteral("0x0427"));
        QVERIFY(m_box->resultText().startsWith(QStringLiteral("read ")));
    }

    void readOnlyObjectIsNotWritten()
    {
        m_box->setAddressText(QStringLiteral("6041:0"));
        QVERIFY(button("read")->isEnabled());
        QVERIFY(!button("write")->isEnabled());
        m_box->setValueText(QStringLiteral("7"));
        m_box->write();
        QVERIFY(m_box->resultText().contains(QStringLiteral("read-only")));
        QVERIFY(m_fake->writes.isEmpty());
    }

    void invalidTextIsRefusedWithMessage_data()
    {
        QTest::addColumn<QString>("address");
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("message");
        QTest::newRow("not a number") << "6081:0"
                                      << "fast"
                                      << "invalid argument";
        QTest::newRow("negative unsigned") << "6081:0"
                                           << "-1"
                                           << "out of range";
        QTest::newRow("integer8 overflow") << "6060:0"
                                           << "300"
                                           << "out of range";
        QTest::newRow("bad address") << "60zz"
                                     << "1"
                                     << "invalid argument";
    }

    void invalidTextIsRefusedWithMessage()
    {
        QFETCH(QString, address);
        QFETCH(QString, text);
        QFETCH(QString, message);
        m_box->setAddressText(address);
        m_box->setValueText(text);
        QSignalSpy finished(m_box.get(), &ObjectAccessBox::finished);
        m_box->write();
        QCOMPARE(finished.count(), 1); // refused at once, nothing sent
        QVERIFY2(m_box->resultText().startsWith(message), qPrintable(m_box->resultText()));
        QVERIFY(m_fake->writes.isEmpty());
    }

    void enumerationNameIsAccepted()
    {
        m_box->setAddressText(QStringLiteral("6060:0"));
        m_box->setValueText(QStringLiteral("Homing"));
        m_box->write();
        QTRY_COMPARE(m_fake->writes.size(), 1);
        QCOMPARE(m_fake->writes.first().second.toLongLong(), 6);
    }

    void deviceErrorIsShownNextToTheValue()
    {
        m_fake->setFailure(
            { 0x6081, 0 },
            Error(Error::Kind::DeviceError, QStringLiteral("ERROR 6081:0 parameter locked")));
        m_box->setAddressText(QStringLiteral("6081:0"));
        m_box->setValueText(QStringLiteral("10"));
        QSignalSpy finished(m_box.get(), &ObjectAccessBox::finished);
        m_box->write();
        QTRY_COMPARE(finished.count(), 1);
        QCOMPARE(finished.first().first().toBool(), false);
        QCOMPARE(m_box->resultText(),
                 QStringLiteral("device error: ERROR 6081:0 parameter locked"));
        QVERIFY(!m_box->isBusy());
    }

    void unknownObjectIsReadAsInteger()
    {
        m_box->setAddressText(QStringLiteral("2fff:0"));
        QVERIFY(m_box->currentDefinition().has_value());
        QVERIFY(button("write")->isEnabled());
        QSignalSpy finished(m_box.get(), &ObjectAccessBox::finished);
        m_box->read();
        QTRY_COMPARE(finished.count(), 1);
        QCOMPARE(m_box->valueText(), QStringLiteral("42"));
        m_box->setHex(true);
        QCOMPARE(m_box->valueText(), QStringLiteral("0x2A"));
    }

    void disconnectedBoxRefusesRequests()
    {
        m_fake->goAway();
        m_box->setAddressText(QStringLiteral("6081:0"));
        QVERIFY(!button("read")->isEnabled());
        QVERIFY(!button("write")->isEnabled());
        m_box->read();
        QCOMPARE(m_box->resultText(), QStringLiteral("not connected"));
    }
};

QTEST_MAIN(TestObjectAccessBox)
#include "tst_objectaccessbox.moc"
