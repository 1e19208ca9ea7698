// Conversions shared by the binding files: JS strings to the core's enums, and errors thrown as JS
// exceptions whose message names the problem. Bindings only; the core never sees emscripten::val.
#pragma once

#include <emscripten/val.h>

#include <cmath>
#include <string>

#include "book.hpp"

namespace conecurl::js {

[[noreturn]] inline void throwError(const char* type, const std::string& message) {
    emscripten::val::global(type).new_(emscripten::val("conecurl: " + message)).throw_();
}

// An Error with a `code` property, for failures JS must tell apart from others without parsing the
// message (e.g. 'webgl2-unavailable', where the component falls back to static pages).
[[noreturn]] inline void throwErrorWithCode(const char* code, const std::string& message) {
    emscripten::val error = emscripten::val::global("Error").new_(emscripten::val("conecurl: " + message));
    error.set("code", emscripten::val(code));
    error.throw_();
}

// Decimal digits of a whole number, without std::to_string (whose snprintf would bring printf's
// float formatting into the wasm).
inline std::string digits(long long n) {
    if (n < 0) return "-" + digits(-n);
    std::string out(1, static_cast<char>('0' + n % 10));
    return n >= 10 ? digits(n / 10) + out : out;
}

// A JS number that must be a whole number in [lo, hi]: anything else (NaN, a string, 2.5, out of
// range) is refused with a RangeError naming the argument, never coerced to 0 behind the caller's back.
inline int wholeNumber(const emscripten::val& value, const char* name, double lo, double hi) {
    const double number = value.isNumber() ? value.as<double>() : NAN;
    if (!(number >= lo && number <= hi) || number != static_cast<double>(static_cast<long long>(number))) {
        throwError("RangeError", std::string(name) + " must be a whole number from " + digits(static_cast<long long>(lo)) +
                                     " to " + digits(static_cast<long long>(hi)));
    }
    return static_cast<int>(number);
}

// A JS number that must be finite and in [lo, hi]; `range` words the bounds for the error ("0 to 1"),
// which keeps printf's float formatting out of the wasm.
inline double finiteNumber(const emscripten::val& value, const char* name, double lo, double hi, const char* range) {
    const double number = value.isNumber() ? value.as<double>() : NAN;
    if (!(number >= lo && number <= hi)) throwError("RangeError", std::string(name) + " must be a number from " + range);
    return number;
}

inline Binding bindingFromString(const std::string& name) {
    if (name == kBindingLeft) return Binding::Left;
    if (name == kBindingRight) return Binding::Right;
    if (name == kBindingTop) return Binding::Top;
    throwError("TypeError", "binding must be 'left', 'right' or 'top', got '" + name + "'");
}

inline const char* toString(Binding binding) {
    switch (binding) {
        case Binding::Left: return kBindingLeft.data();
        case Binding::Right: return kBindingRight.data();
        case Binding::Top: return kBindingTop.data();
    }
    return kBindingLeft.data();
}

}  // namespace conecurl::js
