#!/usr/bin/env python3
# Usage: python3 scripts/diagnosis_matrix.py OUT_ROOT SEEDS(1,2,..) [EFFECTS(a,b,..|none|ooc:EFFECT)] ["extra diagnose args"]
#   hidden effect -> diagnose verdict, recovery, error cut. `ooc:EFFECT` hides EFFECT and diagnoses with a
#   catalogue that lacks it (--effects = every other effect): the out-of-catalogue case, expected "unexplained".
# Diagnosis confusion matrix: hidden effect -> verdict/named effect, parameter recovery (mean, 95 % interval and
# whether it holds the hidden value), error fall.
import subprocess, json, sys, os, math, time
T=os.environ.get('TWIN',os.path.join(os.path.dirname(os.path.abspath(__file__)),'..','build','cli','twin'))
CH='hub_force_fl_N,hub_force_fr_N,hub_force_rl_N,hub_force_rr_N'
def registered_effects():
  """The effect names `twin list` prints (the registry, subsystems/effect.cpp), in its order."""
  out=subprocess.run([T,'list'],check=True,capture_output=True,text=True).stdout.split('\n')
  start=next(i for i,l in enumerate(out) if l.startswith('effects ('))
  names=[]
  for l in out[start+1:]:
    if not l.strip(): break
    if l.startswith('  ') and not l.startswith('   '): names.append(l.split()[0])
  return names
# The hidden value of each case: a choice per effect (strong enough to be seen in these two
# scenarios, inside the prior), so this stays a hand list; the catalogue itself comes from `twin list`.
cases={
 'bump_stop':'bump_stop:stiffness=5e6,gap_m=0.02',
 'damper_asymmetry':'damper_asymmetry:ratio=1.6',
 'strut_friction':'strut_friction:force_N=150',
 'tire_enveloping':'tire_enveloping:length_m=0.2',
 'progressive_spring':'progressive_spring:stiffness3=1e7',
 'speed_dependent_tire_stiffness':'speed_dependent_tire_stiffness:c_v=0.008',
 'anti_roll_bar':'anti_roll_bar:stiffness_front_N_per_m=20000,stiffness_rear_N_per_m=10000',
 'top_mount_compliance':'top_mount_compliance:compliance_m_per_N=3e-6',
 'none':None,
}
registered=registered_effects()
missing=[e for e in registered if e not in cases]
if missing: print('note: no hidden value chosen for', ','.join(missing), '(add a case above to test them)', file=sys.stderr)
unknown=[e for e in cases if e!='none' and e not in registered]
if unknown: sys.exit(f'cases name effects `twin list` does not know: {unknown}')
root=sys.argv[1]; seeds=[int(s) for s in sys.argv[2].split(',')]; names=sys.argv[3].split(',') if len(sys.argv)>3 else list(cases)
extra=sys.argv[4].split() if len(sys.argv)>4 else []
for name in names:
  ooc = name.startswith('ooc:')
  if ooc:
    hidden_name = name[4:]; cases[name] = cases[hidden_name]
  for seed in seeds:
    d=f'{root}/{name.replace(":","_")}_{seed}'; os.makedirs(d,exist_ok=True)
    t0=time.time()
    for sc in ['diag_bump','diag_rough']:
        cmd=[T,'generate','lab','--scenario',sc,'--times','all','--rate','200','--repetitions','3','--channels',CH,'--seed',str(seed),'--out',f'{d}/{sc}.csv','--quiet']
        if cases[name]: cmd+=['--hidden-effect',cases[name]]
        subprocess.run(cmd,check=True)
    cmd=[T,'diagnose','--data',f'{d}/diag_bump.csv','--data',f'{d}/diag_rough.csv','--out',f'{d}/out','--lhs-points','40','--iterations','3000','--burn-in','1000','--starts','2','--candidates','2','--quiet']+extra
    if ooc: cmd+=['--effects',','.join(e for e in registered if e!=hidden_name)]
    elif cases[name]: cmd+=['--apply',name]
    p=subprocess.run(cmd,capture_output=True,text=True)
    if p.returncode: print(name,seed,'FAILED',p.stderr[-500:]); continue
    j=json.load(open(f'{d}/out/diagnosis.json'))
    named=j.get('effect','-')
    rec=''
    if cases[name] and j['ranked'] and not ooc:
        for r in j['ranked']:
            if r['effect']==name:
                hid=dict(kv.split('=') for kv in cases[name].split(':')[1].split(','))
                for k,v in hid.items():
                    pm=r['parameters'].get(name+'.'+k)
                    if pm:
                        lo,hi=pm['ci95']; held='in' if lo<=float(v)<=hi else 'OUT'
                        rec+=f" {k}={pm['mean']:.3g}({100*(pm['mean']/float(v)-1):+.0f}%) 95% [{lo:.3g},{hi:.3g}] {held}"
    fall=''
    if 'before' in j:
        b=j['before']['systematic_rms_noise_sd']; a=j['after']['systematic_rms_noise_sd']
        fall=f" systRMS {b:.3f}->{a:.3f} ({100*(1-a/b) if b>0 else 0:.0f}% cut, after z {j['after']['lack_of_fit_z']:.1f})"
    top=[(r['effect'],round(r['delta_bic'],1)) for r in j['ranked']]
    where = f" where: {j.get('unexplained_location','')[:160]}" if j['verdict']=='unexplained' else ''
    print(f"{name:32s} seed {seed}: verdict {j['verdict']:11s} named {named:30s} base z {j['base']['lack_of_fit_z']:.1f}{rec}{fall} ranked {top} amb {j['ambiguous_with']}{where} [{time.time()-t0:.0f}s]",flush=True)
