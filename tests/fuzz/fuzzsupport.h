#pragma once
// Shared by the fuzz targets. Every target defines LLVMFuzzerTestOneInput and is built twice:
// with libFuzzer (clang, -DDRIVEBENCH_FUZZ=ON, tools/fuzz.sh) to search for new inputs, and as
// a plain program with replay_main.cpp that runs the corpus in the repository (every build;
// ctest runs the replays).
//
// Contract of a target: it must never crash, hang, assert or leak for any input; a violated
// property (a round trip that does not hold, a buffer over its limit) calls finding(), which
// aborts so that both libFuzzer and the replay report it with the input.
#include <QByteArray>
#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

namespace db::fuzz {

// Creates the QCoreApplication that timers, QObject trees and translations need (once).
void ensureApplication();

// Reports a broken property with a message on stderr and aborts.
[[noreturn]] void finding(const char *what);

// Splits an input into typed pieces; reading past the end yields zeros / empty arrays, so a
// target can read what it needs without checking the size first.
class Input
{
public:
    Input(const uint8_t *data, size_t size);

    bool atEnd() const { return m_pos >= m_size; }
    qsizetype remaining() const { return m_size - m_pos; }
    quint8 byte();
    quint16 u16(); // little-endian
    // The next n bytes (fewer at the end).
    QByteArray take(qsizetype n);
    // A piece whose length (0..max) is given by the next byte.
    QByteArray chunk(int max);
    QByteArray rest();

private:
    const char *m_data;
    qsizetype m_size;
    qsizetype m_pos = 0;
};

} // namespace db::fuzz
