// Conversions shared by the binding files: JS strings to the core's enums, and errors thrown as JS
// exceptions whose message names the problem. Bindings only; the core never sees emscripten::val.
#pragma once

#include <emscripten/val.h>

#include <string>

#include "book.hpp"

namespace conecurl::js {

[[noreturn]] inline void throwError(const char* type, const std::string& message) {
    emscripten::val::global(type).new_(emscripten::val("conecurl: " + message)).throw_();
}

inline Binding bindingFromString(const std::string& name) {
    if (name == "left") return Binding::Left;
    if (name == "right") return Binding::Right;
    if (name == "top") return Binding::Top;
    throwError("TypeError", "binding must be 'left', 'right' or 'top', got '" + name + "'");
}

inline const char* toString(Binding binding) {
    switch (binding) {
        case Binding::Left: return "left";
        case Binding::Right: return "right";
        case Binding::Top: return "top";
    }
    return "left";
}

}  // namespace conecurl::js
