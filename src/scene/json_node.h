// A value of a scene file's JSON and where it is in the file, so that every error names
// the file and the JSON path ("scene.json: objects[2].material.shininess: ..."), with the
// readers of its value types, for scene_json.cpp.
#pragma once
#include <array>
#include <cmath>
#include <initializer_list>
#include <string>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "softraster/error.h"

namespace softraster::scene_json {

using nlohmann::json;

// A JSON value and where it is, for error messages.
class Node {
public:
    Node(const json& j, std::string path, const std::string& file) : j_(j), path_(std::move(path)), file_(file) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(file_ + ": " + (path_.empty() ? std::string("top level") : path_) + ": " + what);
    }
    const json& raw() const { return j_; }

    // An object whose keys are all in `allowed`, or in `added_in_v2` when the file is version 2.
    void expect_object(std::initializer_list<const char*> allowed, std::initializer_list<const char*> added_in_v2 = {},
                       int version = 1) const {
        if (!j_.is_object()) fail("expected an object, got " + type_name());
        auto in = [](const std::string& key, std::initializer_list<const char*> list) {
            for (const char* a : list)
                if (key == a) return true;
            return false;
        };
        for (const auto& [key, value] : j_.items()) {
            if (in(key, allowed)) continue;
            if (!in(key, added_in_v2)) Node(value, child_path(key), file_).fail("unknown key");
            if (version < 2) Node(value, child_path(key), file_).fail("a version 2 key in a version 1 file (set \"version\": 2)");
        }
    }
    bool has(const char* key) const { return j_.contains(key); }
    Node operator[](const char* key) const {
        if (!j_.contains(key)) Node(j_, child_path(key), file_).fail("required field is missing");
        return Node(j_.at(key), child_path(key), file_);
    }
    Node at(size_t i) const { return Node(j_.at(i), path_ + "[" + std::to_string(i) + "]", file_); }
    size_t array_size() const {
        if (!j_.is_array()) fail("expected an array, got " + type_name());
        return j_.size();
    }

    double number() const {
        if (!j_.is_number()) fail("expected a number, got " + type_name());
        const double d = j_.get<double>();
        if (!std::isfinite(d)) fail("number is not finite");
        return d;
    }
    double number_in(double lo, double hi, bool lo_open, bool hi_open, const char* range) const {
        const double d = number();
        if (d < lo || d > hi || (lo_open && d == lo) || (hi_open && d == hi))
            fail("value " + j_.dump() + " out of range (" + range + ")");
        return d;
    }
    int integer_in(int lo, int hi) const {
        if (!j_.is_number()) fail("expected an integer, got " + type_name());
        const double d = j_.get<double>();
        if (!std::isfinite(d) || d != std::floor(d)) fail("expected an integer, got " + j_.dump());
        if (d < lo || d > hi) fail("value " + j_.dump() + " out of range (" + std::to_string(lo) + ".." + std::to_string(hi) + ")");
        return int(d);
    }
    bool boolean() const {
        if (!j_.is_boolean()) fail("expected true or false, got " + type_name());
        return j_.get<bool>();
    }
    std::string string() const {
        if (!j_.is_string()) fail("expected a string, got " + type_name());
        return j_.get<std::string>();
    }
    template <size_t N>
    std::array<double, N> numbers() const {
        if (!j_.is_array() || j_.size() != N) fail("expected an array of " + std::to_string(N) + " numbers");
        std::array<double, N> out;
        for (size_t i = 0; i < N; ++i) out[i] = at(i).number();
        return out;
    }
    glm::vec3 vec3() const {
        const auto a = numbers<3>();
        return glm::vec3(float(a[0]), float(a[1]), float(a[2]));
    }
    // A direction: any vector but the zero vector.
    glm::vec3 nonzero_vec3() const {
        const glm::vec3 v = vec3();
        if (glm::length(v) == 0.0f) fail("must not be the zero vector");
        return v;
    }
    glm::vec4 vec4() const {
        const auto a = numbers<4>();
        return glm::vec4(float(a[0]), float(a[1]), float(a[2]), float(a[3]));
    }
    template <class E>
    E choice(std::initializer_list<std::pair<const char*, E>> options) const {
        const std::string s = string();
        std::string names;
        for (const auto& [name, value] : options) {
            if (s == name) return value;
            names += names.empty() ? name : std::string(", ") + name;
        }
        fail("unknown value '" + s + "' (expected one of: " + names + ")");
    }

private:
    std::string child_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
    std::string type_name() const { return j_.type_name(); }

    const json& j_;
    std::string path_;
    const std::string& file_;
};

}  // namespace softraster::scene_json
