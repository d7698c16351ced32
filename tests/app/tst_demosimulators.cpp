// The demo's devices run in a thread of their own: they answer while the window's thread is busy
// and stop with their owner.
#include "demosimulators.h"

#include <QElapsedTimer>
#include <QTcpSocket>
#include <QTest>
#include <QUrl>

using db::gui::DemoSimulators;

namespace {
// The port of "refgo://127.0.0.1:PORT".
quint16 portOf(const QString &uri)
{
    return quint16(QUrl(uri).port());
}

// One RefGo object read on a blocking socket, without running the event loop of this thread:
// the answer up to the prompt '>' that ends it, or what came before the time ran out.
QByteArray readBlocking(QTcpSocket &socket, const QByteArray &request, int ms)
{
    socket.write(request);
    socket.waitForBytesWritten(ms);
    QByteArray answer;
    QElapsedTimer spent;
    spent.start();
    while (!answer.contains('>') && spent.elapsed() < ms) {
        if (socket.waitForReadyRead(int(ms - spent.elapsed())))
            answer += socket.readAll();
    }
    return answer;
}
} // namespace

class TestDemoSimulators : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void devicesAnswerWhileThisThreadIsBusy()
    {
        DemoSimulators demo;
        const auto started = demo.start();
        QVERIFY2(started, qPrintable(started.error().toString()));
        QVERIFY(started->refgoUri.startsWith(QLatin1String("refgo://127.0.0.1:")));
        QVERIFY(started->slcanUri.startsWith(QLatin1String("canopen+slcan://127.0.0.1:")));
        QVERIFY(started->acuUri.startsWith(QLatin1String("vabus://127.0.0.1:")));
        QVERIFY(started->nm17xPort != 0);
        QVERIFY(started->warnings.isEmpty());
        QVERIFY(demo.isRunning());

        // This thread blocks in waitForReadyRead and runs no event loop: only devices in a
        // thread of their own can answer.
        QTcpSocket socket;
        socket.connectToHost(QStringLiteral("127.0.0.1"), portOf(started->refgoUri));
        QVERIFY(socket.waitForConnected(2000));
        const QByteArray answer = readBlocking(socket, "OR6041,0\r", 2000);
        QVERIFY2(answer.contains('>'), answer.constData());
        QVERIFY2(!answer.contains("ERROR"), answer.constData());

        // A second start returns the devices that run.
        const auto again = demo.start();
        QVERIFY(again);
        QCOMPARE(again->refgoUri, started->refgoUri);
    }

    void devicesStopWithTheirOwner()
    {
        quint16 port = 0;
        {
            DemoSimulators demo;
            const auto started = demo.start();
            QVERIFY(started);
            port = portOf(started->refgoUri);
        }
        QTcpSocket socket;
        socket.connectToHost(QStringLiteral("127.0.0.1"), port);
        QVERIFY(!socket.waitForConnected(2000));
        QCOMPARE(socket.error(), QAbstractSocket::ConnectionRefusedError);
    }
};

QTEST_GUILESS_MAIN(TestDemoSimulators)
#include "tst_demosimulators.moc"
