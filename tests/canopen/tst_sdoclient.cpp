// Level 2: the SDO client over a scripted CAN bus, expedited and segmented transfers, byte for
// byte (movingcap.md 4.3, nm170_canopen.md 3.3.5), and every way a transfer can go wrong.

#include "canopen/sdoabort.h"
#include "canopen/sdoclient.h"
#include "scriptedcanbus.h"

#include <QtTest>

using namespace db;
using namespace db::canopen;
using db::test::ScriptedCanBus;

namespace {
constexpr int kShortTimeoutMs = 40;
constexpr int kWaitMs = 5000;
constexpr NodeId kNode = 50; // MovingCap over SLCAN (movingcap.md 4.1)

QByteArray h(const char *hex)
{
    return QByteArray::fromHex(QByteArray(hex).replace(' ', ""));
}
ScriptedCanBus::Line tx(const char *hex, NodeId node = kNode)
{
    return ScriptedCanBus::tx(0x600 + node, hex);
}
ScriptedCanBus::Line rx(const char *hex, NodeId node = kNode)
{
    return ScriptedCanBus::rx(0x580 + node, hex);
}
} // namespace

class TstSdoClient : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init();
    void cleanup();

    void expeditedUploadMovingCapStatusword();
    void expeditedDownloadMovingCapControlword();
    void expeditedDownloadSaveSignature();
    void nm170Vectors_data();
    void nm170Vectors();
    void segmentedUploadOfDeviceName();
    void segmentedDownloadOfTwelveBytes();
    void forcedSegmentedDownloadOfTwoBytes();
    void forcedExpeditedOfFiveBytesIsRefused();
    void toggleNotAlternatedAbortsTheUpload();
    void toggleNotAlternatedAbortsTheDownload();
    void wrongEchoIsDroppedNotTaken();
    void abortGivesDeviceErrorWithText();
    void abortForAnotherObjectIsIgnored();
    void timeoutSendsAbort();
    void lateResponseIsDroppedNotGivenToNextRequest();
    void responseWithoutRequestIsDropped();
    void wrongCommandSpecifierAbortsWithInvalidCommand();
    void segmentedUploadShorterThanAnnouncedFails();
    void handlerGetsTheUploadAndItsNextRequestGoesOutAtOnce();
    void handlerOfATimeoutWaitsOutTheGraceTimeBeforeItsRequest();
    void handlerFailuresKnownAtOnceComeFromTheLoop();
    void queuedUploadWhoseContextIsGoneIsNotSent();

private:
    Result<QVariant> run(Reply *reply) { return Reply::wait(reply, kWaitMs); }
    void checkScript()
    {
        QVERIFY2(m_bus->scriptErrors().isEmpty(),
                 qPrintable(m_bus->scriptErrors().join(QLatin1Char('\n'))));
        QVERIFY(m_bus->scriptDone());
    }

    ScriptedCanBus *m_bus = nullptr;
    SdoClient *m_sdo = nullptr;
};

void TstSdoClient::init()
{
    m_bus = new ScriptedCanBus;
    m_bus->open();
    m_sdo = new SdoClient(m_bus);
}

void TstSdoClient::cleanup()
{
    delete m_sdo;
    delete m_bus;
}

void TstSdoClient::expeditedUploadMovingCapStatusword()
{
    // t63284041600000000000 -> t5B284B41600027040000
    m_bus->play({ tx("40 41 60 00 00 00 00 00"), rx("4B 41 60 00 27 04 00 00") });
    const auto r = run(m_sdo->upload(kNode, { 0x6041, 0 }));
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r->toByteArray(), h("27 04"));
    checkScript();
}

void TstSdoClient::expeditedDownloadMovingCapControlword()
{
    m_bus->play({ tx("2B 40 60 00 0F 00 00 00"), rx("60 40 60 00 00 00 00 00") });
    const auto r = run(m_sdo->download(kNode, { 0x6040, 0 }, h("0F 00")));
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    checkScript();
}

void TstSdoClient::expeditedDownloadSaveSignature()
{
    m_bus->play({ tx("23 10 10 01 73 61 76 65"), rx("60 10 10 01 00 00 00 00") });
    QVERIFY(run(m_sdo->download(kNode, { 0x1010, 1 }, "save")).ok());
    checkScript();
}

void TstSdoClient::nm170Vectors_data()
{
    QTest::addColumn<bool>("upload");
    QTest::addColumn<int>("index");
    QTest::addColumn<int>("sub");
    QTest::addColumn<QByteArray>("data");
    QTest::addColumn<QByteArray>("request");
    QTest::addColumn<QByteArray>("response");
    QTest::addColumn<quint32>("abortCode");
    QTest::newRow("SDO-1") << true << 0x6004 << 0 << h("20 A1 07 00")
                           << h("40 04 60 00 00 00 00 00") << h("43 04 60 00 20 A1 07 00") << 0u;
    QTest::newRow("SDO-2") << false << 0x2003 << 0 << h("40 01 00 00")
                           << h("23 03 20 00 40 01 00 00") << h("60 03 20 00 00 00 00 00") << 0u;
    QTest::newRow("SDO-3") << true << 0x2101 << 0 << h("7F") << h("40 01 21 00 00 00 00 00")
                           << h("4F 01 21 00 7F 00 00 00") << 0u;
    QTest::newRow("SDO-4") << false << 0x2000 << 5 << h("01 00 00 00")
                           << h("23 00 20 05 01 00 00 00") << h("60 00 20 05 00 00 00 00") << 0u;
    QTest::newRow("SDO-5") << false << 0x2000 << 5 << h("02 00 00 00")
                           << h("23 00 20 05 02 00 00 00") << h("80 00 20 05 30 00 09 06")
                           << 0x06090030u;
}

void TstSdoClient::nm170Vectors()
{
    QFETCH(bool, upload);
    QFETCH(int, index);
    QFETCH(int, sub);
    QFETCH(QByteArray, data);
    QFETCH(QByteArray, request);
    QFETCH(QByteArray, response);
    QFETCH(quint32, abortCode);
    constexpr NodeId node = 127;
    m_bus->play(
        { { true, QCanBusFrame(0x67F, request) }, { false, QCanBusFrame(0x5FF, response) } });
    const ObjectAddress address { quint16(index), quint8(sub) };
    const auto r =
        run(upload ? m_sdo->upload(node, address) : m_sdo->download(node, address, data));
    checkScript();
    if (abortCode) {
        QCOMPARE(r.error().kind(), Error::Kind::DeviceError);
        QCOMPARE(r.error().deviceCode(), abortCode);
        QCOMPARE(r.error().message(), abortText(abortCode));
        return;
    }
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    if (upload)
        QCOMPARE(r->toByteArray(), data);
}

void TstSdoClient::segmentedUploadOfDeviceName()
{
    m_bus->play({
        tx("40 08 10 00 00 00 00 00"), rx("41 08 10 00 0E 00 00 00"), tx("60 00 00 00 00 00 00 00"),
        rx("00 4D 6F 76 69 6E 67 43"), // "MovingC"
        tx("70 00 00 00 00 00 00 00"), rx("10 61 70 20 45 54 48 20"), // "ap ETH "
        tx("60 00 00 00 00 00 00 00"), rx("0F 00 00 00 00 00 00 00"), // last, empty
    });
    const auto r = run(m_sdo->upload(kNode, { 0x1008, 0 }));
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r->toByteArray(), QByteArray("MovingCap ETH "));
    checkScript();
}

void TstSdoClient::segmentedDownloadOfTwelveBytes()
{
    m_bus->play({
        tx("21 07 20 00 0C 00 00 00"),
        rx("60 07 20 00 00 00 00 00"),
        tx("00 48 65 6C 6C 6F 20 57"),
        rx("20 00 00 00 00 00 00 00"),
        tx("15 6F 72 6C 64 21 00 00"),
        rx("30 00 00 00 00 00 00 00"),
    });
    QVERIFY(run(m_sdo->download(kNode, { 0x2007, 0 }, "Hello World!")).ok());
    checkScript();
}

void TstSdoClient::forcedSegmentedDownloadOfTwoBytes()
{
    m_bus->play({
        tx("21 40 60 00 02 00 00 00"),
        rx("60 40 60 00 00 00 00 00"),
        tx("0B 0F 00 00 00 00 00 00"),
        rx("20 00 00 00 00 00 00 00"),
    });
    QVERIFY(
        run(m_sdo->download(kNode, { 0x6040, 0 }, h("0F 00"), SdoClient::Mode::Segmented)).ok());
    checkScript();
}

void TstSdoClient::forcedExpeditedOfFiveBytesIsRefused()
{
    const auto r = run(m_sdo->download(kNode, { 0x2007, 0 }, "12345", SdoClient::Mode::Expedited));
    QCOMPARE(r.error().kind(), Error::Kind::InvalidArgument);
    QVERIFY(m_bus->sent().isEmpty());
}

void TstSdoClient::toggleNotAlternatedAbortsTheUpload()
{
    m_bus->play({
        tx("40 08 10 00 00 00 00 00"),
        rx("41 08 10 00 0E 00 00 00"),
        tx("60 00 00 00 00 00 00 00"),
        rx("00 4D 6F 76 69 6E 67 43"),
        tx("70 00 00 00 00 00 00 00"),
        rx("00 61 70 20 45 54 48 20"), // toggle still 0
        tx("80 08 10 00 00 00 03 05"),
    });
    const auto r = run(m_sdo->upload(kNode, { 0x1008, 0 }));
    QCOMPARE(r.error().kind(), Error::Kind::Malformed);
    QCOMPARE(r.error().deviceCode(), abort::ToggleNotAlternated);
    QVERIFY2(r.error().message().contains(QLatin1String("toggle")),
             qPrintable(r.error().message()));
    checkScript();
}

void TstSdoClient::toggleNotAlternatedAbortsTheDownload()
{
    m_bus->play({
        tx("21 07 20 00 0C 00 00 00"),
        rx("60 07 20 00 00 00 00 00"),
        tx("00 48 65 6C 6C 6F 20 57"),
        rx("30 00 00 00 00 00 00 00"), // toggle 1 for t=0
        tx("80 07 20 00 00 00 03 05"),
    });
    const auto r = run(m_sdo->download(kNode, { 0x2007, 0 }, "Hello World!"));
    QCOMPARE(r.error().deviceCode(), abort::ToggleNotAlternated);
    checkScript();
}

void TstSdoClient::wrongEchoIsDroppedNotTaken()
{
    m_sdo->setTimeoutMs(kShortTimeoutMs);
    // The server answers for 6042:0 when 6041:0 was asked: never the value of 6041.
    m_bus->play({ tx("40 41 60 00 00 00 00 00"), rx("4B 42 60 00 27 04 00 00"),
                  tx("80 41 60 00 00 00 04 05") });
    const auto r = run(m_sdo->upload(kNode, { 0x6041, 0 }));
    QCOMPARE(r.error().kind(), Error::Kind::Timeout);
    QCOMPARE(m_sdo->droppedFrames(), 1);
    checkScript();
}

void TstSdoClient::abortGivesDeviceErrorWithText()
{
    m_bus->play({ tx("40 00 30 00 00 00 00 00"), rx("80 00 30 00 00 00 02 06") });
    QSignalSpy log(m_sdo, &SdoClient::logLine);
    const auto r = run(m_sdo->upload(kNode, { 0x3000, 0 }));
    QCOMPARE(r.error().kind(), Error::Kind::DeviceError);
    QCOMPARE(r.error().deviceCode(), 0x06020000u);
    QCOMPARE(r.error().message(), QStringLiteral("object does not exist in the object dictionary"));
    QCOMPARE(log.size(), 1);
    checkScript();
}

void TstSdoClient::abortForAnotherObjectIsIgnored()
{
    m_bus->play({ tx("40 41 60 00 00 00 00 00"), rx("80 00 30 00 00 00 02 06"),
                  rx("4B 41 60 00 37 02 00 00") });
    const auto r = run(m_sdo->upload(kNode, { 0x6041, 0 }));
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r->toByteArray(), h("37 02"));
    QCOMPARE(m_sdo->droppedFrames(), 1);
}

void TstSdoClient::timeoutSendsAbort()
{
    m_sdo->setTimeoutMs(kShortTimeoutMs);
    m_bus->play({ tx("40 41 60 00 00 00 00 00"), tx("80 41 60 00 00 00 04 05") });
    QElapsedTimer clock;
    clock.start();
    const auto r = run(m_sdo->upload(kNode, { 0x6041, 0 }));
    QCOMPARE(r.error().kind(), Error::Kind::Timeout);
    QVERIFY2(r.error().message().contains(QLatin1String("node 50")),
             qPrintable(r.error().message()));
    QVERIFY(clock.elapsed() >= kShortTimeoutMs - 5);
    checkScript();
}

void TstSdoClient::lateResponseIsDroppedNotGivenToNextRequest()
{
    m_sdo->setTimeoutMs(kShortTimeoutMs);
    m_bus->play({ tx("40 41 60 00 00 00 00 00"), tx("80 41 60 00 00 00 04 05") });
    const auto first = run(m_sdo->upload(kNode, { 0x6041, 0 }));
    QCOMPARE(first.error().kind(), Error::Kind::Timeout);
    // The same object again, and the first answer arrives late, before the second is sent.
    Reply *second = m_sdo->upload(kNode, { 0x6041, 0 });
    m_bus->feed(0x5B2, "4B 41 60 00 11 11 00 00");
    QCOMPARE(m_sdo->droppedFrames(), 1);
    m_bus->play({ tx("40 41 60 00 00 00 00 00"), rx("4B 41 60 00 27 04 00 00") });
    const auto r = run(second);
    QVERIFY2(r.ok(), qPrintable(r.error().toString()));
    QCOMPARE(r->toByteArray(), h("27 04"));
    checkScript();
}

void TstSdoClient::responseWithoutRequestIsDropped()
{
    m_bus->feed(0x5B2, "4B 41 60 00 27 04 00 00");
    m_bus->feed(0x5B3, "60 40 60 00 00 00 00 00");
    QCOMPARE(m_sdo->droppedFrames(), 2);
    QVERIFY(m_bus->sent().isEmpty());
}

void TstSdoClient::wrongCommandSpecifierAbortsWithInvalidCommand()
{
    m_bus->play({ tx("40 41 60 00 00 00 00 00"), rx("60 41 60 00 00 00 00 00"),
                  tx("80 41 60 00 01 00 04 05") });
    const auto r = run(m_sdo->upload(kNode, { 0x6041, 0 }));
    QCOMPARE(r.error().kind(), Error::Kind::Malformed);
    QCOMPARE(r.error().deviceCode(), abort::InvalidCommand);
    checkScript();
}

void TstSdoClient::segmentedUploadShorterThanAnnouncedFails()
{
    m_bus->play({
        tx("40 08 10 00 00 00 00 00"),
        rx("41 08 10 00 0E 00 00 00"),
        tx("60 00 00 00 00 00 00 00"),
        rx("01 4D 6F 76 69 6E 67 43"), // last after 7
        tx("80 08 10 00 13 00 07 06"),
    });
    const auto r = run(m_sdo->upload(kNode, { 0x1008, 0 }));
    QCOMPARE(r.error().kind(), Error::Kind::Malformed);
    checkScript();
}

// The handler gets the upload from the receive handler; a request it makes is sent before it
// returns.
void TstSdoClient::handlerGetsTheUploadAndItsNextRequestGoesOutAtOnce()
{
    QObject context;
    QList<QByteArray> values;
    qsizetype sentInHandler = -1;
    m_bus->play({ tx("40 41 60 00 00 00 00 00"), rx("4B 41 60 00 27 04 00 00"),
                  tx("40 64 60 00 00 00 00 00") });
    m_sdo->upload(kNode, { 0x6041, 0 }, Completion(&context, [&](const Result<QVariant> &r) {
                      values.append(r.ok() ? r->toByteArray() : QByteArray("error"));
                      m_sdo->upload(kNode, { 0x6064, 0 },
                                    Completion(&context, [&](const Result<QVariant> &r2) {
                                        values.append(r2.ok() ? r2->toByteArray()
                                                              : QByteArray("error"));
                                    }));
                      sentInHandler = m_bus->sent().size();
                  }));
    QTRY_COMPARE(values.size(), 1);
    QCOMPARE(values.first(), h("27 04"));
    QCOMPARE(sentInHandler, 2);
    m_bus->feed(0x5B2, "43 64 60 00 10 00 00 00");
    QCOMPARE(values.size(), 2);
    QCOMPARE(values.last(), h("10 00 00 00"));
    checkScript();
}

// A request made by the handler of a timed-out upload waits out the grace time, so a late
// answer to the first cannot be taken for it.
void TstSdoClient::handlerOfATimeoutWaitsOutTheGraceTimeBeforeItsRequest()
{
    m_sdo->setTimeoutMs(kShortTimeoutMs);
    m_bus->play({ tx("40 41 60 00 00 00 00 00"), tx("80 41 60 00 00 00 04 05") });
    QObject context;
    qsizetype sentInHandler = -1;
    std::optional<Result<QVariant>> second;
    m_sdo->upload(kNode, { 0x6041, 0 }, Completion(&context, [&](const Result<QVariant> &r) {
                      QCOMPARE(r.error().kind(), Error::Kind::Timeout);
                      m_sdo->upload(
                          kNode, { 0x6041, 0 },
                          Completion(&context, [&](const Result<QVariant> &r2) { second = r2; }));
                      sentInHandler = m_bus->sent().size();
                  }));
    QTRY_COMPARE(sentInHandler, 2); // the request and the abort, not the second request
    m_bus->feed(0x5B2, "4B 41 60 00 11 11 00 00"); // late answer to the first
    QCOMPARE(m_sdo->droppedFrames(), 1);
    checkScript();
    m_bus->play({ tx("40 41 60 00 00 00 00 00"), rx("4B 41 60 00 27 04 00 00") });
    QTRY_VERIFY(second);
    QVERIFY2(second->ok(), qPrintable(second->error().toString()));
    QCOMPARE(second->value().toByteArray(), h("27 04"));
    checkScript();
}

// Failures known in the call (bad node, bus closed, too much for expedited) reach the handler
// from the event loop, never from inside the call.
void TstSdoClient::handlerFailuresKnownAtOnceComeFromTheLoop()
{
    QObject context;
    QList<Error::Kind> kinds;
    const auto record = [&](const Result<QVariant> &r) {
        kinds.append(r.error().kind());
    };
    m_sdo->upload(0, { 0x6041, 0 }, Completion(&context, record));
    m_sdo->download(kNode, { 0x6040, 0 }, h("01 02 03 04 05"), Completion(&context, record),
                    SdoClient::Mode::Expedited);
    m_bus->close();
    m_sdo->upload(kNode, { 0x6041, 0 }, Completion(&context, record));
    QVERIFY(kinds.isEmpty());
    QTRY_COMPARE(kinds.size(), 3);
    QCOMPARE(kinds,
             QList<Error::Kind>({ Error::Kind::InvalidArgument, Error::Kind::InvalidArgument,
                                  Error::Kind::Disconnected }));
    QVERIFY(m_bus->sent().isEmpty());
}

// A requester withdraws a queued upload by deleting its context.
void TstSdoClient::queuedUploadWhoseContextIsGoneIsNotSent()
{
    QObject keeps;
    auto withdrawn = std::make_unique<QObject>();
    int called = 0;
    const auto count = [&](const Result<QVariant> &) {
        ++called;
    };
    m_bus->play({ tx("40 41 60 00 00 00 00 00"), rx("4B 41 60 00 27 04 00 00"),
                  tx("40 64 60 00 00 00 00 00"), rx("43 64 60 00 10 00 00 00") });
    m_sdo->upload(kNode, { 0x6041, 0 }, Completion(&keeps, count));
    m_sdo->upload(kNode, { 0x1000, 0 }, Completion(withdrawn.get(), count));
    m_sdo->upload(kNode, { 0x6064, 0 }, Completion(&keeps, count));
    withdrawn.reset();
    QTRY_COMPARE(called, 2);
    checkScript();
    QCOMPARE(m_sdo->pending(kNode), 0);
}

QTEST_GUILESS_MAIN(TstSdoClient)
#include "tst_sdoclient.moc"
