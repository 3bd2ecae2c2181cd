// report.h -- a tiny JSON writer for build/reports/*.json (figures that the
// tables of README.md and docs/*.md are generated from).
#pragma once
#include <cstdio>
#include <string>
#include <sys/stat.h>

class JsonReport {
public:
    JsonReport() : s_("{") {}
    // Integers (counts) exactly, other numbers to 9 significant digits.
    JsonReport &num(const char *key, double v) {
        char b[64];
        if (v == static_cast<double>(static_cast<long long>(v)) && v < 9.0e15 && v > -9.0e15)
            std::snprintf(b, sizeof b, "%lld", static_cast<long long>(v));
        else
            std::snprintf(b, sizeof b, "%.9g", v);
        return raw(key, b);
    }
    JsonReport &str(const char *key, const std::string &v) {
        std::string q = "\"";
        for (char c : v) { if (c == '"' || c == '\\') q += '\\'; q += c; }
        return raw(key, q + "\"");
    }
    JsonReport &raw(const char *key, const std::string &json) {
        if (s_.size() > 1) s_ += ",\n  "; else s_ += "\n  ";
        s_ += "\""; s_ += key; s_ += "\": "; s_ += json;
        return *this;
    }
    std::string text() const { return s_ + "\n}\n"; }
    bool write(const std::string &path) const {
        mkdir("build", 0777);
        mkdir("build/reports", 0777);
        FILE *f = std::fopen(path.c_str(), "w");
        if (!f) { std::fprintf(stderr, "cannot write %s\n", path.c_str()); return false; }
        std::fputs(text().c_str(), f);
        std::fclose(f);
        return true;
    }
private:
    std::string s_;
};
