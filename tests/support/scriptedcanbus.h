#pragma once

#include "transport/canbus.h"

#include <QCanBusFrame>
#include <QList>
#include <QStringList>

namespace db::test {

// A CanBus for level-2 tests: records every frame the engine sends, lets the test feed received
// frames, refuse the open or drop the bus, and can play a python-canopen-style script of
// expected TX and scripted RX frames:
//
//   bus.play({ tx(0x632, "40 41 60 00 00 00 00 00"), rx(0x5B2, "4B 41 60 00 27 04 00 00") });
//
// Each frame sent is compared with the next TX line (mismatches go to scriptErrors()); the RX
// lines that follow it, up to the next TX line, are then delivered from the event loop, in
// order. RX lines at the start of a script are delivered as soon as play() is called.
// open() succeeds (or fails, after refuseNextOpen()) at once, inside the call.
class ScriptedCanBus : public CanBus
{
    Q_OBJECT
public:
    struct Line
    {
        bool tx = false;
        QCanBusFrame frame;
    };
    // Payload as hex, spaces allowed: "40 41 60 00".
    static Line tx(quint32 id, const char *hex);
    static Line rx(quint32 id, const char *hex);
    static QCanBusFrame frame(quint32 id, const char *hex);

    using CanBus::CanBus;

    QString name() const override { return QStringLiteral("scripted can0"); }

    const QList<QCanBusFrame> &sent() const { return m_sent; }
    // Frames sent since the last takeSent().
    QList<QCanBusFrame> takeSent();

    // Delivers a frame as received, now (only while open).
    void feed(const QCanBusFrame &frame) { deliver(frame); }
    void feed(quint32 id, const char *hex) { deliver(frame(id, hex)); }
    // Delivers a frame from the event loop.
    void feedLater(const QCanBusFrame &frame);

    void play(const QList<Line> &script);
    // True when every line of the script has been sent or delivered.
    bool scriptDone() const { return m_next >= m_script.size(); }
    const QStringList &scriptErrors() const { return m_errors; }

    void refuseNextOpen(const Error &error) { m_refusal = error; }
    void drop(const Error &error) { setClosed(error); }

Q_SIGNALS:
    void frameWritten(const QCanBusFrame &frame);

protected:
    void doOpen() override;
    void doClose() override { setClosed(); }
    void doSend(const QCanBusFrame &frame) override;

private:
    void deliverReplies();

    QList<QCanBusFrame> m_sent;
    qsizetype m_taken = 0;
    QList<Line> m_script;
    qsizetype m_next = 0;
    QStringList m_errors;
    Error m_refusal;
};

// "632 [8] 40 41 60 00 00 00 00 00" for test messages.
QString describe(const QCanBusFrame &frame);

} // namespace db::test
