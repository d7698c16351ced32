#pragma once

#include <QFile>
#include <QIODevice>

#include <cstdio>

namespace db::cli {

// A write-only device in front of stdout or stderr that lets no control character through but
// the line feed: whatever a command prints (values, names and error messages quoted from a
// device or a file), an ESC sequence, CR, NUL or a bidi override reaches the terminal as a
// visible escape (db::printable(), line feeds kept). Bytes arrive UTF-8 encoded from a
// QTextStream; an incomplete UTF-8 sequence at the end of a piece (at most 3 bytes) waits for the
// next piece, and is escaped as it is when the device closes.
class TerminalDevice : public QIODevice
{
public:
    explicit TerminalDevice(FILE *stream);
    ~TerminalDevice() override;

    bool isSequential() const override { return true; }
    void close() override;

protected:
    qint64 readData(char *, qint64) override { return -1; }
    qint64 writeData(const char *data, qint64 size) override;

private:
    void emitEscaped(QByteArrayView bytes);

    QFile m_file;
    QByteArray m_pending; // the unfinished UTF-8 sequence of the last piece, 0..3 bytes
};

} // namespace db::cli
