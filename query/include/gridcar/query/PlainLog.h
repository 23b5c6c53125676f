#pragma once
/// @file PlainLog.h
/// @brief OMPL's log as a user reads it: the message, without the source file and line.

namespace gridcar
{
/**
 * @brief Makes OMPL print its log (ours goes through it too) on stderr as "Warning: message",
 * "Error: ...", "Info: ...", "Debug: ...", without the " at line N in FILE" OMPL's default
 * handler adds: where in OMPL's or gridcar's sources a message was raised is of no use to the
 * user of a program or of the Python package. The level filter (ompl::msg::setLogLevel) still
 * applies. The handler lives as long as the process (OMPL keeps a pointer to it); it writes
 * one line per message with one stdio call, so messages from threads do not interleave.
 */
void usePlainLog();

}  // namespace gridcar
