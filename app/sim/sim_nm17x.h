#pragma once

#include <QString>

#include <optional>

namespace db::sim {

// `drivebench-sim nm17x`: a line of simulated NM17x displays (devices/nm17x/device/nm17xsim.h).
struct Nm17xOptions
{
    QString devices; // "nm172@127,nm172@127,nm174@5"
    std::optional<QString> slcanPort;
    std::optional<QString> virtualCan;
    std::optional<QString> controlPort;
    // The bus's bit rate in bit/s: SLCAN clients set to another one (Sn) hear nothing. Empty:
    // 125000, the displays' delivery rate.
    std::optional<QString> bitrate;
};

// Runs until the event loop ends (SIGINT/SIGTERM); 2 for bad options, 3 when a door cannot open.
int runNm17x(const Nm17xOptions &options, void (*quitOnSignals)());

} // namespace db::sim
