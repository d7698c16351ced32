#pragma once

// LSS master (CiA 305): switch mode global/selective, configure node id and bit timing, store,
// inquire identity and node id, fastscan.
//
// Contracts:
// - One confirmed service at a time: a request made while another runs fails with Busy.
//   Unconfirmed services (switch global, activate bit timing) return false when the bus is not
//   open.
// - Confirmed services return a Reply the caller owns; it finishes with the answer, with
//   DeviceError carrying the slave's error code (configure/store), or with Timeout after
//   timeoutMs(). Answers that do not match the request are ignored.
// - Frame lengths: CiA 305 sends every request with DLC 8 (Full, the default). Compact uses the
//   shorter DLCs the NM170 manual shows (nm170_canopen.md 2.3/2.4: "04 01", "11 25", "17 00").

#include "canopenids.h"
#include "core/reply.h"
#include "lss.h"

#include <QPointer>
#include <QTimer>

namespace db {
class CanBus;
}
class QCanBusFrame;

namespace db::canopen {

class LssMaster : public QObject
{
    Q_OBJECT
public:
    enum class FrameLength { Full, Compact };

    static constexpr int kDefaultTimeoutMs = 500;
    // Fastscan reads "no answer" as a 1 bit, so each step waits this long for silence.
    static constexpr int kDefaultFastscanStepMs = 20;

    // The bus is not owned and must outlive the master.
    explicit LssMaster(CanBus *bus, QObject *parent = nullptr);

    int timeoutMs() const { return m_timeoutMs; }
    void setTimeoutMs(int ms) { m_timeoutMs = qMax(1, ms); }
    int fastscanStepMs() const { return m_fastscanStepMs; }
    void setFastscanStepMs(int ms) { m_fastscanStepMs = qMax(1, ms); }
    void setFrameLength(FrameLength length) { m_frameLength = length; }
    bool isBusy() const { return !m_reply.isNull(); }

    bool switchModeGlobal(LssMode mode);
    // Selects the one slave with this address into configuration mode (40h..43h, answer 44h).
    Reply *switchModeSelective(const LssAddress &address);
    Reply *configureNodeId(NodeId node); // 1..127, or lss::kUnconfigured
    Reply *configureBitTiming(quint8 tableIndex, quint8 tableSelector = 0);
    bool activateBitTiming(quint16 switchDelayMs);
    Reply *storeConfiguration();
    // cs 5Ah..5Eh (lss::InquireVendor ... lss::InquireNodeId); value: the number (qulonglong).
    Reply *inquire(quint8 cs);
    // Finds one unconfigured slave and leaves it in configuration mode; value:
    // QVariant::fromValue(LssAddress). Timeout when no unconfigured slave answers.
    Reply *fastscan();

    // The request frames (pure; for tests and the CAN monitor).
    QCanBusFrame frame(quint8 cs, const QByteArray &data, int compactLength) const;

private:
    enum class Op { None, Confirm, Inquire, Fastscan };
    Reply *begin(Op op, quint8 answerCs);
    void onFrame(const QCanBusFrame &frame);
    void onTimeout();
    void finish(const Error &error, const QVariant &value = {});
    void send(quint8 cs, const QByteArray &data, int compactLength);
    // Fastscan steps (CiA 305 8.3.2.6): reset, then per part 32 bit probes and a confirmation.
    void fastscanSend();
    void fastscanStep(bool answered);

    CanBus *m_bus;
    QTimer m_timer;
    QPointer<Reply> m_reply;
    Op m_op = Op::None;
    quint8 m_answerCs = 0;
    int m_timeoutMs = kDefaultTimeoutMs;
    int m_fastscanStepMs = kDefaultFastscanStepMs;
    FrameLength m_frameLength = FrameLength::Full;
    // fastscan state
    quint32 m_id[4] = {};
    int m_sub = 0;
    int m_bit = -1; // -1: reset step; 32: confirmation step of m_sub
};

} // namespace db::canopen
