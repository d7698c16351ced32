#pragma once

#include "commands.h"

namespace db::cli {

// CANopen commands (README "CANopen"). scan, nmt --all and lss work on the bus of the URI and
// need no ?node=; nmt (single node), pdo and dcf use the URI's node.
int scan(Context &context); // scan URI: one line per node
int nmt(Context &context); // nmt URI start|stop|preop|reset|reset-comm [--all]
int lss(Context &context); // lss URI inquire|switch-global|switch-selective|set-node|...
int pdo(Context &context); // pdo URI: the node's PDO configuration
int dcf(Context &context); // dcf URI -o FILE: DCF of the device's current values

// --file for read/write: the value as raw bytes (strings UTF-8, domains as is, numbers by their
// type's encoding), written atomically / read whole.
int saveValueToFile(Context &context, DataType type, const QVariant &raw);
Result<QVariant> loadValueFromFile(const Context &context, const ObjectDef *def, DataType type);

} // namespace db::cli
