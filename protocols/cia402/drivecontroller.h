#pragma once

#include "sequence.h"
#include "statusword.h"

namespace db::cia402 {

// Drives the CiA 402 power state machine (movingcap.md 5.2, 5.3) of one drive over any
// DeviceConnection. Each request reads the statusword, plans the controlword steps from the
// present state to the wanted one and checks every step against the statusword within
// kStepTimeoutMs (a Sequence). The reply's value is the final statusword.
//
// Path to Operation enabled (transition numbers of CiA 402):
//   Fault -15-> Switch on disabled -2-> Ready to switch on -3-> Switched on -4-> Operation enabled
//   Quick stop active -12-> Switch on disabled (then as above)
// A fault that appears on the way fails the request (DeviceError) instead of waiting it out.
//
// Only one request runs at a time: a new one cancels the older one (its reply fails with
// Cancelled), so the last word wins - a disable always overrides a pending enable.
class DriveController : public QObject
{
    Q_OBJECT
public:
    static constexpr int kStepTimeoutMs = 1000;
    static constexpr int kQuickStopTimeoutMs = 3000; // braking to standstill may take a while

    explicit DriveController(DeviceConnection *connection, QObject *parent = nullptr);

    // Each returns a reply the caller owns; it finishes exactly once.
    Reply *shutdown(); // -> Ready to switch on
    Reply *switchOn(); // -> Switched on
    Reply *enableOperation(); // -> Operation enabled
    Reply *disableVoltage(); // -> Switch on disabled (a faulted drive counts as off)
    Reply *quickStop(); // Operation enabled -11-> Quick stop active (or on to Switch on disabled)
    Reply *faultReset(); // Fault -15-> Switch on disabled (0 -> 0x80 edge); no-op without fault

    // The planned controlword steps from `from` to `to` (pure; for tests and the plan above).
    // Each step is {controlword, state expected after it}. Empty when no path exists.
    struct Step
    {
        quint16 controlword;
        State expected;
    };
    static QList<Step> plan(State from, State to);

    DeviceConnection *connection() const { return m_connection; }

private:
    Reply *goTo(State target, const QString &name);
    Reply *run(Sequence *sequence);

    DeviceConnection *m_connection;
    QPointer<Sequence> m_running;
};

} // namespace db::cia402
