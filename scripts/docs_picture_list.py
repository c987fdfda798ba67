"""Every picture in docs/validation/ and how it is made: the runs it comes from (case file and
overrides, or a stored table) and the commands that draw it. Read by scripts/docs_pictures.py.

A run is `grainload run CASE --set ...` into RUNS/<id>/, a `grainload trade` sweep into
RUNS/<id>/, or a case script that makes its own runs there. `minutes` is the wall time measured
on the shared 2-core development machine, on one thread beside other jobs (2026-12-05; the
runs not made that day: their pages' figures), for choosing what to rerun.
In the drawing commands {id} stands for a run's folder, {docs} for docs/validation and
{grainload} for the executable.
"""

from dataclasses import dataclass, field


@dataclass
class Run:
    case: str
    sets: list = field(default_factory=list)
    minutes: float = 1.0
    kind: str = "run"            # run | trade | script
    arguments: list = field(default_factory=list)  # trade: its options; script: the command
    done: str = "summary.json"   # the file that says the run is complete


@dataclass
class Picture:
    files: list
    page: str
    runs: list
    draw: list                   # commands, each a list: ["python"|"xvfb"|"copy", ...]
    table: str = ""              # a stored table the picture is drawn from, instead of runs


HOPPER_12MM = ['sph.body[0].spacing=12.5 mm', 'sph.body[0].shape.base=0 23.13 mm',
               'sph.body[0].shape.base_radius=179.43 mm', 'sph.wall[0].spacing=6.25 mm',
               'sph.wall[1].spacing=6.25 mm', 'sph.wall[2].spacing=6.25 mm']
PLATE_14MM = ['sph.body[0].spacing=14.4 mm', 'sph.body[0].shape.min=-36 -36 26.64 mm',
              'sph.body[0].shape.max=36 36 213.84 mm', 'sph.wall[0].spacing=7.2 mm']
# The collapse runs of the profile picture: the viscosity's c not pinned (the case files'
# pin came later), stiffness by the moduli, to 0.5 s.
PLATE_UNPINNED = ['sph.artificial_viscosity.sound_speed=0 m/s', 'case.end_time=0.5 s']
K_1000 = ['material[0].bulk_modulus=30.62 MPa', 'material[0].shear_modulus=8.23 MPa']
K_10 = ['material[0].bulk_modulus=3.062 GPa', 'material[0].shear_modulus=0.823 GPa']
RIGID_055 = ['coupling.interface[0].rigid=true',
             'coupling.friction[0].mu_static=0.55', 'coupling.friction[0].mu_kinetic=0.45',
             'sph.friction[0].mu_static=0.55', 'sph.friction[0].mu_kinetic=0.45',
             'case.reference[0].value="0 kg"',
             'case.reference[0].source="thesis section 7.4: with mu_s = 0.55, mu_k = 0.45 the '
             'wagon empties completely"']
SILO_TRADE = ['--vary', 'material[0].stiffness_scale=1,0.5,0.25',
              '--link', 'sph.contact.stiffness=5 MPa,2.5 MPa,1.25 MPa',
              '--vary', 'sph.cfl_safety=0.3,0.6', '--figures',
              'sink_below_steady_rate,wall_map_rest_normal_force,wall_map_flow_normal_force,'
              'wall_map_flow_peak_max_pressure,wall_map_rest_peak_mean_pressure',
              '--budget', '5%', '--jobs', '1']
HOPPER_TRADE = ['--vary', 'material[0].stiffness_scale=1,0.5,0.25',
                '--link', 'sph.contact.stiffness=0.3 MPa,0.15 MPa,0.075 MPa',
                '--vary', 'sph.cfl_safety=0.3,0.6',
                '--figures', 'sink_below_steady_rate,sink_below_discharged_mass',
                '--budget', '5%', '--jobs', '1']

RUNS = {
    "silo_janssen_fill_small": Run("cases/silo_janssen/silo_janssen_fill_small.toml",
                                   minutes=0.6),
    "silo_rest_small": Run("cases/silo/silo_rest_small.toml", minutes=0.4),
    "silo_rest": Run("cases/silo/silo_rest.toml", minutes=7.3),
    "silo_discharge_small": Run("cases/silo/silo_discharge_small.toml", minutes=0.4),
    "silo_discharge": Run("cases/silo/silo_discharge.toml", minutes=5.4),
    "silo_discharge_trade": Run("cases/silo/silo_discharge_small.toml", minutes=1.5, kind="trade",
                                arguments=SILO_TRADE, done="trade.csv"),
    "hopper_discharge_small": Run("cases/hopper_discharge/hopper_discharge_small.toml",
                                  minutes=0.15),
    "hopper_discharge": Run("cases/hopper_discharge/hopper_discharge.toml", minutes=0.6),
    "hopper_discharge_12mm": Run("cases/hopper_discharge/hopper_discharge.toml", minutes=3.6,
                                 sets=HOPPER_12MM + ['sph.body[0].shape.top_radius=853.17 mm',
                                                     'sph.body[0].shape.height=1167.0 mm',
                                                     'case.end_time=3 s']),
    "hopper_discharge_6mm": Run("cases/hopper_discharge/hopper_discharge.toml", minutes=17, sets=[
        'sph.body[0].spacing=6.25 mm', 'sph.body[0].shape.base=0 11.563 mm',
        'sph.body[0].shape.base_radius=189.72 mm', 'sph.body[0].shape.top_radius=855.39 mm',
        'sph.body[0].shape.height=1153.0 mm', 'sph.wall[0].spacing=3.125 mm',
        'sph.wall[1].spacing=3.125 mm', 'sph.wall[2].spacing=3.125 mm', 'case.end_time=2.6 s']),
    "hopper_deposition": Run("cases/hopper_discharge/hopper_deposition.toml", minutes=0.7),
    "hopper_deposition_12mm": Run("cases/hopper_discharge/hopper_deposition.toml", minutes=3.9,
                                  sets=HOPPER_12MM + [
                                      'sph.body[0].shape.top_radius=201.08 mm',
                                      'sph.body[0].shape.height=37.5 mm',
                                      'sph.source[0].shape.base=0 60.63 mm',
                                      'sph.source[0].shape.base_radius=201.08 mm',
                                      'sph.source[0].shape.top_radius=853.17 mm',
                                      'sph.source[0].shape.height=1129.5 mm',
                                      'case.end_time=5.4 s']),
    "hopper_drop": Run("cases/hopper_discharge/hopper_drop.toml", minutes=0.6),
    "hopper_discharge_trade": Run("cases/hopper_discharge/hopper_discharge_small.toml",
                                  minutes=0.6, kind="trade", arguments=HOPPER_TRADE,
                                  done="trade.csv"),
    "column_collapse_2d": Run("cases/column_collapse_2d/column_collapse_2d.toml", minutes=13),
    "column_collapse_2d_aspect_sweep": Run(
        "cases/column_collapse_2d/column_collapse_2d.toml", minutes=23, kind="script",
        arguments=["python", "cases/column_collapse_2d/aspect_sweep.py", "{grainload}",
                   "{self}"], done="aspect_sweep.csv"),
    "column_collapse_2d_aspect_sweep_mu_i": Run(
        "cases/column_collapse_2d/column_collapse_2d_mu_i.toml", minutes=9, kind="script",
        arguments=["python", "cases/column_collapse_2d/aspect_sweep.py", "{grainload}", "{self}",
                   "--case", "cases/column_collapse_2d/column_collapse_2d_mu_i.toml",
                   "--aspects", "0.5,1,2,3,4,6,8"], done="aspect_sweep.csv"),
    "inclined_plane_2mm": Run("cases/inclined_plane/bagnold_mu_i_small.toml", minutes=0.3),
    "inclined_plane_1mm": Run("cases/inclined_plane/bagnold_mu_i.toml", minutes=2.5),
    "inclined_plane_05mm": Run("cases/inclined_plane/bagnold_mu_i.toml", minutes=17,
                               sets=["sph.body[0].spacing=0.5 mm",
                                     "sph.body[0].shape.min=0 0.925 mm",
                                     "sph.body[0].shape.max=20 20.925 mm",
                                     "sph.wall[0].spacing=0.25 mm",
                                     "sph.wall[0].origin=0.125 0 mm",
                                     "sph.wall[0].edge_u=19.75 0 mm"]),
    "collapse_plate_k1000_a0.1_14mm": Run("cases/column_collapse/column_collapse_plate.toml",
                                          minutes=0.3, sets=K_1000 + PLATE_14MM + PLATE_UNPINNED),
    "collapse_plate_k10_a0.1_14mm": Run("cases/column_collapse/column_collapse_plate.toml",
                                        minutes=2.7, sets=K_10 + PLATE_14MM + PLATE_UNPINNED),
    "collapse_plate_k1000_a3.162_14mm": Run(
        "cases/column_collapse/column_collapse_plate.toml", minutes=0.5,
        sets=K_1000 + PLATE_14MM + PLATE_UNPINNED + ['sph.artificial_viscosity.alpha=3.162']),
    "collapse_plate_k1000_a0.1_7mm": Run("cases/column_collapse/column_collapse_plate.toml",
                                         minutes=5, sets=K_1000 + PLATE_UNPINNED),
    "silo_hopper": Run("cases/silo_hopper/silo_hopper.toml", minutes=11.2),
    "silo_hopper_fine": Run("cases/silo_hopper/silo_hopper_fine.toml", minutes=21),
    "silo_hopper_12mm": Run("cases/silo_hopper/silo_hopper_12mm.toml", minutes=27),
    "hopper_wagon": Run("cases/hopper_wagon/hopper_wagon.toml", minutes=20.4),
    "hopper_wagon_rigid_0.55": Run("cases/hopper_wagon/hopper_wagon.toml", minutes=27,
                                   sets=RIGID_055),
}


def trade_plot(name, page, table, budget, figures=""):
    """A trade plot drawn from a trade table stored beside its case file."""
    command = ["python", "scripts/plot_trade.py", table, "{docs}/" + name, "--budget", budget]
    return Picture([name], page, [], [command + (["--figures", figures] if figures else [])],
                   table=table)


def copied(run, made, name, page, draw):
    """A picture a case script writes into its run's folder, copied to docs/validation."""
    return Picture([name], page, [run], [draw, ["copy", "{" + run + "}/" + made, "{docs}/" + name]])


PICTURES = [
    # Trade plots: the sweeps' tables are stored beside their case files.
    trade_plot("column_collapse_trade.svg", "column_collapse.md",
               "cases/column_collapse/column_collapse.trade.csv",
               "0.02", "heap_final_height,heap_run_out,heap_time_to_rest"),
    trade_plot("column_collapse_2d_trade.svg", "column_collapse_2d.md",
               "cases/column_collapse_2d/column_collapse_2d.trade.csv", "0.05",
               "heap_final_height,heap_run_out,heap_angle,heap_time_to_rest"),
    trade_plot("hopper_discharge_trade_25mm.svg", "hopper_discharge.md",
               "cases/hopper_discharge/hopper_discharge.trade.csv", "0.05",
               "sink_below_steady_rate,sink_below_discharged_mass"),
    trade_plot("hopper_wagon_trade.svg", "hopper_wagon.md",
               "cases/hopper_wagon/hopper_wagon.trade.csv", "0.05"),
    trade_plot("silo_discharge_trade_full.svg", "silo.md", "cases/silo/silo_discharge.trade.csv",
               "0.05"),
    trade_plot("silo_hopper_trade.svg", "silo_hopper.md",
               "cases/silo_hopper/silo_hopper.trade.csv", "0.05"),
    # Trade plots of sweeps short enough to run here.
    Picture(["hopper_discharge_trade.svg"], "hopper_discharge.md", ["hopper_discharge_trade"],
            [["python", "scripts/plot_trade.py", "{hopper_discharge_trade}/trade.csv",
              "{docs}/hopper_discharge_trade.svg", "--budget", "0.05"]]),
    Picture(["silo_discharge_trade.svg"], "silo.md", ["silo_discharge_trade"],
            [["python", "scripts/plot_trade.py", "{silo_discharge_trade}/trade.csv",
              "{docs}/silo_discharge_trade.svg", "--budget", "0.05"]]),
    # The slot silo and the coupled Janssen cylinder.
    copied("silo_janssen_fill_small", "silo_janssen_fill.png", "silo_janssen_fill_small.png",
           "coupling.md", ["python", "cases/silo_janssen/analyse.py", "{silo_janssen_fill_small}"]),
    Picture(["silo_janssen_fill_small_wall_map.png"], "coupling.md", ["silo_janssen_fill_small"],
            [["python", "scripts/plot_wall_map.py", "{silo_janssen_fill_small}", "wall", "--png",
              "{docs}/silo_janssen_fill_small_wall_map.png"]]),
    copied("silo_rest_small", "silo_pressure.png", "silo_rest_small_pressure.png", "silo.md",
           ["python", "cases/silo/analyse.py", "{silo_rest_small}", "25"]),
    copied("silo_rest", "silo_pressure.png", "silo_rest_pressure.png", "silo.md",
           ["python", "cases/silo/analyse.py", "{silo_rest}", "12.5"]),
    Picture(["silo_discharge_small.png"], "silo.md", ["silo_discharge_small"],
            [["python", "cases/silo/analyse_discharge.py", "{silo_discharge_small}", "--png",
              "{docs}/silo_discharge_small.png"]]),
    Picture(["silo_discharge_full.png"], "silo.md", ["silo_discharge"],
            [["python", "cases/silo/analyse_discharge.py", "{silo_discharge}", "--png",
              "{docs}/silo_discharge_full.png"]]),
    # The plane-wedge hopper.
    Picture(["hopper_discharge.svg"], "hopper_discharge.md",
            ["hopper_discharge_small", "hopper_discharge", "hopper_discharge_12mm",
             "hopper_discharge_6mm"],
            [["python", "cases/hopper_discharge/analyse.py", "{hopper_discharge_small}",
              "{hopper_discharge}", "{hopper_discharge_12mm}", "{hopper_discharge_6mm}",
              "--label", "50 mm", "--label", "25 mm", "--label", "12.5 mm", "--label", "6.25 mm",
              "--svg", "{docs}/hopper_discharge.svg"]]),
    Picture(["hopper_deposition.svg"], "hopper_discharge.md",
            ["hopper_discharge", "hopper_deposition", "hopper_discharge_12mm",
             "hopper_deposition_12mm", "hopper_drop"],
            [["python", "cases/hopper_discharge/analyse.py", "{hopper_discharge}",
              "{hopper_deposition}", "{hopper_discharge_12mm}", "{hopper_deposition_12mm}",
              "{hopper_drop}", "--label", "25 mm placed", "--label", "25 mm deposited",
              "--label", "12.5 mm placed", "--label", "12.5 mm deposited",
              "--label", "25 mm dropped", "--svg", "{docs}/hopper_deposition.svg"]]),
    # The column collapses.
    Picture(["column_collapse_2d_profile.svg"], "column_collapse_2d.md", ["column_collapse_2d"],
            [["python", "cases/column_collapse_2d/analyse.py", "{column_collapse_2d}", "--svg",
              "{docs}/column_collapse_2d_profile.svg"]]),
    copied("column_collapse_2d_aspect_sweep", "aspect_sweep.svg",
           "column_collapse_2d_aspect_sweep.svg", "column_collapse_2d.md",
           ["python", "cases/column_collapse_2d/aspect_sweep.py", "{grainload}",
            "{column_collapse_2d_aspect_sweep}", "--analyse-only"]),
    Picture(["column_collapse_2d_aspect_sweep_mu_i.svg"], "column_collapse_2d.md",
            ["column_collapse_2d_aspect_sweep_mu_i", "column_collapse_2d_aspect_sweep"],
            [["python", "cases/column_collapse_2d/aspect_sweep.py", "{grainload}",
              "{column_collapse_2d_aspect_sweep_mu_i}", "--aspects", "0.5,1,2,3,4,6,8",
              "--analyse-only", "--label", "grainload SPH, μ(I)", "--beside",
              "{column_collapse_2d_aspect_sweep}", "--beside-label",
              "grainload SPH, Drucker–Prager"],
             ["copy", "{column_collapse_2d_aspect_sweep_mu_i}/aspect_sweep.svg",
              "{docs}/column_collapse_2d_aspect_sweep_mu_i.svg"]]),
    # The inclined plane's steady flow against Bagnold's profile.
    Picture(["inclined_plane_profile.svg"], "inclined_plane.md",
            ["inclined_plane_2mm", "inclined_plane_1mm", "inclined_plane_05mm"],
            [["python", "cases/inclined_plane/analyse.py", "{inclined_plane_2mm}",
              "{inclined_plane_1mm}", "{inclined_plane_05mm}", "--label", "SPH, 2 mm",
              "--label", "SPH, 1 mm", "--label", "SPH, 0.5 mm", "--svg",
              "{docs}/inclined_plane_profile.svg"]]),
    Picture(["column_collapse_profiles.png"], "column_collapse.md",
            ["collapse_plate_k1000_a0.1_14mm", "collapse_plate_k10_a0.1_14mm",
             "collapse_plate_k1000_a3.162_14mm", "collapse_plate_k1000_a0.1_7mm"],
            [["python", "cases/column_collapse/plot_profiles.py",
              "{docs}/column_collapse_profiles.png",
              "1/1000, α 0.1, 14.4 mm={collapse_plate_k1000_a0.1_14mm}/frames/"
              "column_collapse_plate_000010.vtm",
              "1/10, α 0.1, 14.4 mm={collapse_plate_k10_a0.1_14mm}/frames/"
              "column_collapse_plate_000010.vtm",
              "1/1000, α 3.162 (≡ ×1), 14.4 mm={collapse_plate_k1000_a3.162_14mm}/frames/"
              "column_collapse_plate_000010.vtm",
              "1/1000, α 0.1, 7.2 mm={collapse_plate_k1000_a0.1_7mm}/frames/"
              "column_collapse_plate_000010.vtm"]]),
    # The circular silo.
    copied("silo_hopper", "silo_hopper_pressure.png", "silo_hopper_pressure.png", "silo_hopper.md",
           ["python", "cases/silo_hopper/analyse.py", "{silo_hopper}"]),
    Picture(["silo_hopper_t0250.png", "silo_hopper_t0400.png"], "silo_hopper.md", ["silo_hopper"],
            [["xvfb", "scripts/render_frames.py", "{silo_hopper}", "--times", "2.5,4",
              "--mirror", "x,y", "--prefix", "silo_hopper", "--size", "500x800",
              "--view", "30,10"],
             ["copy", "{silo_hopper}/pictures/silo_hopper_t0250.png",
              "{docs}/silo_hopper_t0250.png"],
             ["copy", "{silo_hopper}/pictures/silo_hopper_t0400.png",
              "{docs}/silo_hopper_t0400.png"]]),
    copied("silo_hopper_fine", "silo_hopper_pressure.png", "silo_hopper_fine_pressure.png",
           "silo_hopper.md", ["python", "cases/silo_hopper/analyse.py", "{silo_hopper_fine}"]),
    copied("silo_hopper_12mm", "silo_hopper_pressure.png", "silo_hopper_12mm_pressure.png",
           "silo_hopper.md", ["python", "cases/silo_hopper/analyse.py", "{silo_hopper_12mm}"]),
    # The hopper wagon.
    Picture(["hopper_wagon_t0250.png", "hopper_wagon_t0300.png", "hopper_wagon_t0400.png",
             "hopper_wagon_t1100.png"], "hopper_wagon.md", ["hopper_wagon"],
            [["xvfb", "scripts/render_frames.py", "{hopper_wagon}", "--times", "2.5,3,4,11",
              "--mirror", "x,y", "--walls", "door", "--view=-35,35", "--size", "1000x560",
              "--prefix", "hopper_wagon"]]
            + [["copy", "{hopper_wagon}/pictures/" + n, "{docs}/" + n]
               for n in ("hopper_wagon_t0250.png", "hopper_wagon_t0300.png",
                         "hopper_wagon_t0400.png", "hopper_wagon_t1100.png")]),
    Picture(["hopper_wagon_von_mises_t0250.png"], "hopper_wagon.md", ["hopper_wagon"],
            [["xvfb", "scripts/render_frames.py", "{hopper_wagon}", "--times", "2.5", "--color",
              "von_mises", "--mirror", "x,y", "--view=-35,30", "--size", "1000x560", "--prefix",
              "hopper_wagon_von_mises"],
             ["copy", "{hopper_wagon}/pictures/hopper_wagon_von_mises_t0250.png",
              "{docs}/hopper_wagon_von_mises_t0250.png"]]),
    Picture(["hopper_wagon_discharge.png"], "hopper_wagon.md",
            ["hopper_wagon", "hopper_wagon_rigid_0.55"],
            [["python", "cases/hopper_wagon/analyse_discharge.py", "{hopper_wagon}",
              "{hopper_wagon_rigid_0.55}", "--png", "{docs}/hopper_wagon_discharge.png",
              "--labels", "elastic 0.65/0.55,rigid 0.55/0.45"]]),
]
