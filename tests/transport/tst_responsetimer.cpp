// ResponseTimer: the time limit a request engine restarts for every request. It fires once, at
// the last deadline given (a restart moves it later or earlier), never after stop(), and
// restarting it for request after request registers no new dispatcher timer.
#include "transport/responsetimer.h"
#include "wait.h"

#include <QAbstractEventDispatcher>
#include <QElapsedTimer>
#include <QTest>
#include <QTimer>

using namespace db;

class TestResponseTimer : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void firesOnceAfterItsInterval()
    {
        int fired = 0;
        QElapsedTimer clock;
        qint64 firedAtMs = -1;
        ResponseTimer timer([&] {
            ++fired;
            firedAtMs = clock.elapsed();
        });
        clock.start();
        timer.start(20);
        QVERIFY(timer.isActive());
        QVERIFY(test::waitFor([&] { return fired > 0; }));
        QVERIFY2(firedAtMs >= 20, qPrintable(QString::number(firedAtMs)));
        QVERIFY(!timer.isActive());
        // Nothing more comes: a marker timer started later fires first.
        bool marker = false;
        QTimer::singleShot(60, this, [&] { marker = true; });
        QVERIFY(test::waitFor([&] { return marker; }));
        QCOMPARE(fired, 1);
    }

    // The dispatcher timer still runs for the first deadline; the callback waits for the new one.
    void restartMovesTheDeadlineLater()
    {
        int fired = 0;
        QElapsedTimer clock;
        qint64 firedAtMs = -1;
        ResponseTimer timer([&] {
            ++fired;
            firedAtMs = clock.elapsed();
        });
        clock.start();
        timer.start(40);
        bool restarted = false;
        QTimer::singleShot(20, this, [&] {
            restarted = true;
            timer.start(40); // due at 60 ms or later, not at 40
        });
        QVERIFY(test::waitFor([&] { return fired > 0; }));
        QVERIFY(restarted);
        QVERIFY2(firedAtMs >= 60, qPrintable(QString::number(firedAtMs)));
        QCOMPARE(fired, 1);
    }

    void restartMovesTheDeadlineEarlier()
    {
        int fired = 0;
        QElapsedTimer clock;
        ResponseTimer timer([&] { ++fired; });
        clock.start();
        timer.start(60000);
        timer.start(10);
        QVERIFY(test::waitFor([&] { return fired > 0; }, 30000));
        QVERIFY2(clock.elapsed() < 60000, qPrintable(QString::number(clock.elapsed())));
    }

    void stopPreventsTheCallback()
    {
        int fired = 0;
        ResponseTimer timer([&] { ++fired; });
        timer.start(10);
        timer.stop();
        QVERIFY(!timer.isActive());
        bool marker = false;
        QTimer::singleShot(50, this, [&] { marker = true; });
        QVERIFY(test::waitFor([&] { return marker; }));
        QCOMPARE(fired, 0);
    }

    // A client sending request after request arms and disarms the limit each time; the
    // dispatcher keeps the one timer it registered, instead of one registration per request.
    void restartsRegisterNoNewDispatcherTimer()
    {
        ResponseTimer timer([] {});
        auto *dispatcher = QAbstractEventDispatcher::instance();
        timer.start(1000);
        const auto registered = dispatcher->registeredTimers(&timer);
        QCOMPARE(registered.size(), 1);
        for (int i = 0; i < 1000; ++i) {
            timer.stop();
            timer.start(1000);
        }
        const auto after = dispatcher->registeredTimers(&timer);
        QCOMPARE(after.size(), 1);
        QCOMPARE(after.at(0).timerId, registered.at(0).timerId);
    }
};

QTEST_GUILESS_MAIN(TestResponseTimer)
#include "tst_responsetimer.moc"
