#pragma once

// Looking for NM17x displays at several bit rates. The displays are delivered at 125 kbit/s, but
// their bit-rate object 2100h defaults to 250 kbit/s, so a line may answer at either. Each bit
// rate gets a CAN bus of its own, opened from the URI of the line's bus with its bitrate
// replaced, and closed again after the look (a node at another bit rate hears nothing).
//
// Contracts:
// - start() once; finished() comes exactly once, after every bit rate was looked at, also when
//   a bus cannot be opened (that bit rate then names its problem).
// - The buses are this object's own; the caller's bus is not touched.

#include "nm17xline.h"

#include "core/connectionuri.h"

#include <QObject>

#include <memory>

namespace db::nm17x {

struct BitrateResult
{
    int bitrate = 0; // bit/s
    QList<DisplayState> displays;
    QString problem; // the bus did not open, or a display failed to answer its state
};

class BitrateScan : public QObject
{
    Q_OBJECT
public:
    static constexpr int kDefaultOpenMs = 3000;
    static constexpr int kDefaultSdoMs = 500;

    // uri: any URI of the line's bus (its ?node= and ?bitrate= are ignored).
    BitrateScan(const ConnectionUri &uri, const QList<int> &bitrates, QObject *parent = nullptr);
    ~BitrateScan() override;

    void setTimeouts(int openMs, int sdoMs);
    void start();
    bool isRunning() const;
    QList<BitrateResult> results() const;
    // The bit rates at which at least one display answered.
    QList<int> answeringBitrates() const;

    // "125000,250000" -> bit rates; InvalidArgument names the bad item.
    static Result<QList<int>> parseBitrates(const QString &text);
    static QList<int> defaultBitrates(); // 125000, 250000

Q_SIGNALS:
    void bitrateDone(int bitrate, int displays);
    void finished();

private:
    void next();

    struct Private;
    std::unique_ptr<Private> d;
};

} // namespace db::nm17x
