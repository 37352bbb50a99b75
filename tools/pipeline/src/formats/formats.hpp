// The built-in readers and writers, one function per entry, each in its own file here;
// src/registry.cpp lists them. Adding a format: a file with its function, and one line there.
#pragma once

#include "fapc/pipeline/registry.hpp"

namespace fapc::pipeline::builtin {

InputFormat fap_input();
InputFormat fba_input();
InputFormat mp4_input();
InputFormat mimic_input();
InputFormat fml_input();
InputFormat xmto_input();
InputFormat combine_input();
InputFormat bml_input();       // format_bml.cpp
InputFormat xml_input();       // format_xml.cpp: by the root element
InputFormat fml_apml_input();  // format_intent.cpp
InputFormat apml_input();      // format_intent.cpp
InputFormat smil_input();      // format_smil.cpp: Xface SMIL-Agent

OutputFormat fap_output();
OutputFormat fba_output();
OutputFormat mp4_output();
OutputFormat xmta_scene_output();
OutputFormat xmta_commands_output();
OutputFormat curves_json_output();
OutputFormat svg_output();  // the plots (format_svg.cpp)
OutputFormat pdf_output();
OutputFormat csv_output();
OutputFormat timeline_output();
OutputFormat png_output();  // the face (format_face.cpp)
OutputFormat webm_output();
OutputFormat html_output();
OutputFormat wav_output();  // the voice (format_wav.cpp)
OutputFormat glb_output();  // the 3D head (format_gltf.cpp)
OutputFormat gltf_output();

}  // namespace fapc::pipeline::builtin
