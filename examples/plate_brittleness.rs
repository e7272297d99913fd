//! The energy-criterion cracked plate (seed §5) with its toughness scaled, to see how the DEM
//! behaves as the plate moves towards small-scale yielding, and how much energy it dissipates.
//!
//! usage: cargo run --release --example plate_brittleness -- K_FACTOR traction|rollers LEVELS [RUN_FRACTION]
//!   K_FACTOR      multiplies K_Ic (and so G_f by its square); 1 is the seed's plate
//!   LEVELS        refinement levels, e.g. 0,1,2 (element diameter a/4, a/8, a/16, ...)
//!   RUN_FRACTION  part of the loading time to run (the peak of a tougher plate comes early)
//!
//! Prints per level the peak far-field stress beside the handbook LEFM value (eq 4.3) scaled by
//! K_FACTOR, and the plastic work and fracture energy of the ledger per unit ligament area in
//! units of G_f. Loading is twice as slow as the validation study's (`LOADING_TIME_S`).
//! Figures quoted in the issue-2 note come from `... -- 0.25 traction 0,1,2,3 0.4` and
//! `... -- 1 traction 0,1` / `... -- 1 rollers 0,1`.

use demsweep::cases::cracked_plate::{self as plate, Grips, Setup, Study};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: plate_brittleness K_FACTOR traction|rollers LEVELS [RUN_FRACTION]";
    let k_factor: f64 = args.first().and_then(|s| s.parse().ok()).expect(usage);
    let grips = match args.get(1).map(String::as_str) {
        Some("traction") => Grips::UniformTraction,
        Some("rollers") => Grips::Rollers,
        _ => panic!("{usage}"),
    };
    let levels: Vec<u32> = args.get(2).expect(usage).split(',').map(|s| s.parse().expect(usage)).collect();
    let run_fraction: f64 = args.get(3).map_or(1.0, |s| s.parse().expect(usage));
    let setup = Setup { grips, loading_time_s: 2.0 * plate::LOADING_TIME_S, ..Setup::default() };
    let k = plate::TOUGHNESS_PA_SQRT_M * k_factor;
    let g_f = k * k / plate::MODULUS_PA;
    let lefm = plate::handbook_pa() * k_factor;
    println!("K_Ic = {k:.4e} Pa√m, G_f = {g_f:.4e} N/m, handbook (long strip, LEFM) {lefm:.4e} Pa");
    for &level in &levels {
        let mut scene = plate::scene(Study::EnergyClosePacked, level, true, &setup);
        scene.scene.duration_s *= run_fraction;
        for m in &mut scene.material {
            m.fracture_toughness_pa_sqrt_m *= k_factor;
        }
        let built = scene.build().expect("scene");
        let n = built.model.el.len();
        let result = demsweep::run::run(built, &mut |_| {}).expect("run");
        let stress = plate::peak_force_n(&result) / (plate::net_width_m(Study::EnergyClosePacked, level) * plate::THICKNESS_M);
        let get = |c: &str| result.summary_table().get(0, c).expect(c).parse::<f64>().expect(c);
        let per_gf = |j: f64| j / ((plate::WIDTH_M - plate::CRACK_M) * plate::THICKNESS_M * g_f);
        println!(
            "level {level}: {n} elements, peak {stress:.5e} Pa ({:+.2} % vs handbook); bonds broken {}, plastic work {:.3} and fracture energy {:.3} G_f per unit ligament area",
            100.0 * (stress / lefm - 1.0),
            get("bonds_broken"),
            per_gf(get("plastic_work_j")),
            per_gf(get("fracture_energy_j")),
        );
    }
}
