// The project's one error style, used by softraster, vkref and crosscheck alike:
//   Status     success, or one error line (an operation that returns no value);
//   Result<T>  a T, or the Status saying why there is none (an operation that returns a value).
// The library never prints: an error travels outward as a value, each layer that knows more
// context prefixing it ("scene.json: draws[0]: ..."), and only a program's main() prints it.
// Deliberately no exceptions across these boundaries and no error codes: every error a user
// sees is one line of text, and that line is all the caller needs.
#pragma once

#include <cassert>
#include <optional>
#include <string>
#include <utility>

namespace softraster {

class Status {
 public:
  Status() = default;  // success
  static Status error(std::string message) { return Status(std::move(message)); }

  bool ok() const { return message_.empty(); }
  explicit operator bool() const { return ok(); }
  const std::string& message() const { return message_; }

  // The same error with `context` in front ("context: message"); success stays success.
  Status prefixed(const std::string& context) const {
    return ok() ? Status() : Status(context + ": " + message_);
  }

 private:
  explicit Status(std::string message) : message_(std::move(message)) {
    if (message_.empty()) message_ = "unknown error";
  }
  std::string message_;
};

// A value or an error. Converts from a T (success) and from a failed Status (error).
template <class T>
class Result {
 public:
  Result(T value) : value_(std::move(value)) {}  // NOLINT: implicit, so `return value;` works
  Result(Status error) : status_(std::move(error)) {  // NOLINT: implicit, so `return Status::error(...)` works
    assert(!status_.ok() && "a Result is built from a failed Status only");
    if (status_.ok()) status_ = Status::error("unknown error");
  }

  bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }
  const Status& status() const { return status_; }
  const std::string& error() const { return status_.message(); }

  T& value() & { return *value_; }
  const T& value() const& { return *value_; }
  T&& value() && { return std::move(*value_); }
  T& operator*() & { return *value_; }
  const T& operator*() const& { return *value_; }
  T&& operator*() && { return std::move(*value_); }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }

 private:
  std::optional<T> value_;
  Status status_;
};

}  // namespace softraster
