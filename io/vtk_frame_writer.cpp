#include "io/vtk_frame_writer.hpp"

#include "io/atomic_file.hpp"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

namespace grainload::io {

namespace {

const char* const kTensorComponentNames[6] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};

vtkNew<vtkDoubleArray> to_vtk(const FieldArray& field) {
    vtkNew<vtkDoubleArray> array;
    array->SetName(field.name.c_str());
    array->SetNumberOfComponents(field.components);
    const auto tuples = static_cast<vtkIdType>(field.values.size()) / field.components;
    array->SetNumberOfTuples(tuples);
    std::copy(field.values.begin(), field.values.end(), array->GetPointer(0));
    if (field.components == 6) {
        for (int c = 0; c < 6; ++c) {
            array->SetComponentName(c, kTensorComponentNames[c]);
        }
    }
    return array;
}

vtkNew<vtkPoints> to_vtk_points(const std::vector<Vec3>& points) {
    vtkNew<vtkPoints> vtk_points;
    vtk_points->SetDataTypeToDouble();
    vtk_points->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        vtk_points->SetPoint(static_cast<vtkIdType>(i), points[i].data());
    }
    return vtk_points;
}

/// VTK composes the file in memory and it goes out in one write, atomically: written to a file,
/// VTK's XML writer issued some 700 small writes and seeks per frame, which cost a few
/// milliseconds of system calls on the 2-vCPU machine of docs/performance.md ("Frames and
/// the heap").
template <class Writer> void configure_and_write(Writer& writer, const std::string& path) {
    writer->WriteToOutputStringOn();
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorTypeToZLib();
    if (writer->Write() != 1) {
        throw std::runtime_error("VTK could not write " + path);
    }
    const std::string text = writer->GetOutputString();
    write_file_atomically(
        path,
        [&](std::ostream& out) {
            out.write(text.data(), static_cast<std::streamsize>(text.size()));
        },
        true);
}

void add_arrays(vtkDataSetAttributes* attributes, const std::vector<FieldArray>& fields) {
    for (const auto& field : fields) {
        attributes->AddArray(to_vtk(field));
    }
}

/// Points (each a vertex) and lines are poly data (.vtp); shells an unstructured grid (.vtu).
const char* extension(const Block& block) {
    return block.kind == Block::Kind::shell ? ".vtu" : ".vtp";
}

void write_poly_block(const Block& block, const std::string& path) {
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(to_vtk_points(block.points));
    vtkNew<vtkCellArray> cells;
    if (block.kind == Block::Kind::lines) {
        for (const auto& cell : block.cells) {
            const vtkIdType ends[2] = {cell[0], cell[1]};
            cells->InsertNextCell(2, ends);
        }
        poly->SetLines(cells);
    } else {
        for (vtkIdType i = 0; i < static_cast<vtkIdType>(block.points.size()); ++i) {
            cells->InsertNextCell(1, &i);
        }
        poly->SetVerts(cells);
    }
    add_arrays(poly->GetPointData(), block.point_arrays);
    add_arrays(poly->GetCellData(), block.cell_arrays);
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(poly);
    configure_and_write(writer, path);
}

} // namespace

VtkFrameWriter::VtkFrameWriter(std::string directory, std::string case_name)
    : directory_(std::move(directory)), case_name_(std::move(case_name)) {
    std::filesystem::create_directories(directory_ + "/frames");
}

std::string VtkFrameWriter::frame_stem(std::size_t index) const {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "_%06zu", index);
    return case_name_ + buffer;
}

void VtkFrameWriter::write_block(const Block& block, const std::string& path) const {
    if (block.kind != Block::Kind::shell) {
        write_poly_block(block, path);
    } else {
        vtkNew<vtkUnstructuredGrid> grid;
        grid->SetPoints(to_vtk_points(block.points));
        grid->Allocate(static_cast<vtkIdType>(block.cells.size()));
        for (const auto& cell : block.cells) {
            const vtkIdType ids[4] = {cell[0], cell[1], cell[2], cell[3]};
            const bool triangle = cell[3] < 0;
            grid->InsertNextCell(triangle ? VTK_TRIANGLE : VTK_QUAD, triangle ? 3 : 4, ids);
        }
        add_arrays(grid->GetPointData(), block.point_arrays);
        add_arrays(grid->GetCellData(), block.cell_arrays);
        vtkNew<vtkXMLUnstructuredGridWriter> writer;
        writer->SetInputData(grid);
        configure_and_write(writer, path);
    }
}

void VtkFrameWriter::write_multiblock_index(const Frame& frame, std::size_t index) const {
    const std::string stem = frame_stem(index);
    write_file_atomically(directory_ + "/frames/" + stem + ".vtm", [&](std::ostream& out) {
        out << "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\" "
               "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
               "  <vtkMultiBlockDataSet>\n";
        for (std::size_t b = 0; b < frame.blocks.size(); ++b) {
            const auto& block = frame.blocks[b];
            out << "    <DataSet index=\"" << b << "\" name=\"" << block.name << "\" file=\""
                << stem << '/' << block.name << extension(block) << "\"/>\n";
        }
        out << "  </vtkMultiBlockDataSet>\n</VTKFile>\n";
    });
}

void VtkFrameWriter::write_collection() const {
    write_file_atomically(directory_ + "/" + case_name_ + ".pvd", [&](std::ostream& out) {
        out << "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
               "  <Collection>\n";
        for (std::size_t i = 0; i < times_.size(); ++i) {
            // Shortest text that reads back as the same double: "0.2", not "0.20000000000000001".
            char time[32];
            const auto end = std::to_chars(time, time + sizeof time, times_[i]).ptr;
            out << "    <DataSet timestep=\"" << std::string_view(time, end - time)
                << "\" file=\"frames/" << frame_stem(i) << ".vtm\"/>\n";
        }
        out << "  </Collection>\n</VTKFile>\n";
    });
}

std::string VtkFrameWriter::last_frame_path() const {
    return times_.empty() ? std::string()
                          : directory_ + "/frames/" + frame_stem(times_.size() - 1) + ".vtm";
}

std::string VtkFrameWriter::write(const Frame& frame) {
    const std::size_t index = times_.size();
    const std::string stem = frame_stem(index);
    const std::string piece_directory = directory_ + "/frames/" + stem;
    std::filesystem::create_directories(piece_directory);
    for (const auto& block : frame.blocks) {
        write_block(block, piece_directory + "/" + block.name + extension(block));
    }
    write_multiblock_index(frame, index);
    times_.push_back(frame.time);
    write_collection();
    return last_frame_path();
}

} // namespace grainload::io
