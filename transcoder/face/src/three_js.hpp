// three.js as compiled into the program (transcoder/face/EmbedThreeJs.cmake, from Debian's
// libjs-three r111): the files the preview page's 3D view puts in its own <script> elements.
#pragma once

#include <span>
#include <string_view>

namespace fapc::face {

struct ScriptFile {
  std::string_view name;  // three.min.js, GLTFLoader.js, OrbitControls.js
  std::string_view text;
};

// In load order: the library first, then the two examples that extend its THREE global.
std::span<const ScriptFile> three_js_sources();

// three.js's licence (MIT), which each page that carries the library must carry too.
inline constexpr std::string_view kThreeJsLicence =
    "three.js r111 (https://threejs.org), from Debian's libjs-three.\n"
    "Copyright (c) 2010-2019 three.js authors\n\n"
    "Permission is hereby granted, free of charge, to any person obtaining a copy of this software and\n"
    "associated documentation files (the \"Software\"), to deal in the Software without restriction,\n"
    "including without limitation the rights to use, copy, modify, merge, publish, distribute,\n"
    "sublicense, and/or sell copies of the Software, and to permit persons to whom the Software is\n"
    "furnished to do so, subject to the following conditions:\n\n"
    "The above copyright notice and this permission notice shall be included in all copies or\n"
    "substantial portions of the Software.\n\n"
    "THE SOFTWARE IS PROVIDED \"AS IS\", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR IMPLIED, INCLUDING BUT\n"
    "NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY, FITNESS FOR A PARTICULAR PURPOSE AND\n"
    "NONINFRINGEMENT. IN NO EVENT SHALL THE AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES\n"
    "OR OTHER LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM, OUT OF OR IN\n"
    "CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE SOFTWARE.\n";

}  // namespace fapc::face
