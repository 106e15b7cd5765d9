var iu="fleetlink.token",su="fleetlink.principal",cs={token(){return sessionStorage.getItem(iu)},principal(){return sessionStorage.getItem(su)},set(n,e){sessionStorage.setItem(iu,n),sessionStorage.setItem(su,e)},clear(){sessionStorage.removeItem(iu),sessionStorage.removeItem(su)},wsUrl(){let n=location.protocol==="https:"?"wss:":"ws:",e=this.token();return`${n}//${location.host}/${e?`?token=${encodeURIComponent(e)}`:""}`}};var Yo=class extends Error{constructor(t,i){super(i);this.status=t}status};async function yi(n,e={}){let t=new Headers(e.headers),i=cs.token();i&&t.set("Authorization",`Bearer ${i}`),e.body&&t.set("Content-Type","application/json");let s=await fetch(n,{...e,headers:t,cache:"no-store"}),r=await s.text(),o=null;try{o=r?JSON.parse(r):null}catch{o=r}if(!s.ok)throw new Yo(s.status,o&&o.error||r||`HTTP ${s.status}`);return o}var Ut={frames:{},poses:{},feedback:[],lastResult:null,lastServiceResponse:null,disabled:{},renders:0,cloudAgesMs:[],busyMs:{decode:0,cloudUnpack:0,cloudRender:0},mapToScreen:null};function si(n){Ut.frames[n]=(Ut.frames[n]??0)+1}globalThis.fleetlink=Ut;var _e={POS_INT:0,NEG_INT:1,BYTE_STRING:2,UTF8_STRING:3,ARRAY:4,MAP:5,TAG:6,SIMPLE_FLOAT:7},wt={DATE_STRING:0,DATE_EPOCH:1,POS_BIGINT:2,NEG_BIGINT:3,DECIMAL_FRAC:4,BIGFLOAT:5,BASE64URL_EXPECTED:21,BASE64_EXPECTED:22,BASE16_EXPECTED:23,CBOR:24,URI:32,BASE64URL:33,BASE64:34,MIME:36,DATE_EPOCH_DAYS:100,SET:258,JSON:262,WTF8:273,SYMBOL:280,DATE_FULL:1004,REGEXP:21066,SELF_DESCRIBED:55799,INVALID_16:65535,INVALID_32:4294967295,INVALID_64:0xffffffffffffffffn},ct={ZERO:0,ONE:24,TWO:25,FOUR:26,EIGHT:27,INDEFINITE:31},Yi={FALSE:20,TRUE:21,NULL:22,UNDEFINED:23},Kt=class{static BREAK=Symbol.for("github.com/hildjj/cbor2/break");static ENCODED=Symbol.for("github.com/hildjj/cbor2/cbor-encoded");static LENGTH=Symbol.for("github.com/hildjj/cbor2/length")},Xr={MIN:-(2n**63n),MAX:2n**64n-1n};var Qe=class n{static#e=new Map;tag;contents;constructor(e,t=void 0){this.tag=e,this.contents=t}get noChildren(){return!!n.#e.get(this.tag)?.noChildren}static registerDecoder(e,t,i){let s=this.#e.get(e);return this.#e.set(e,t),s&&("comment"in t||(t.comment=s.comment),"noChildren"in t||(t.noChildren=s.noChildren)),i&&!t.comment&&(t.comment=()=>`(${i})`),s}static clearDecoder(e){let t=this.#e.get(e);return this.#e.delete(e),t}static getDecoder(e){return this.#e.get(e)}static getAllDecoders(){return new Map(this.#e)}*[Symbol.iterator](){yield this.contents}push(e){return this.contents=e,1}decode(e){let t=e?.tags?.get(this.tag)??(e?.ignoreGlobalTags?void 0:n.#e.get(this.tag));return t?t(this,e):this}comment(e,t){let i=e?.tags?.get(this.tag)??(e?.ignoreGlobalTags?void 0:n.#e.get(this.tag));if(i?.comment)return i.comment(this,e,t)}toCBOR(){return[this.tag,this.contents]}[Symbol.for("nodejs.util.inspect.custom")](e,t,i){return`${this.tag}(${i(this.contents,t)})`}};function Ns(n){if(n!=null&&typeof n=="object")return n[Kt.ENCODED]}function Qd(n){if(n!=null&&typeof n=="object")return n[Kt.LENGTH]}function Ds(n,e){Object.defineProperty(n,Kt.ENCODED,{configurable:!0,enumerable:!1,value:e})}function Us(n,e){let t=Object(n);return Ds(t,e),t}var ru=Symbol("CBOR_RANGES");function ep(n,e){Object.defineProperty(n,ru,{configurable:!1,enumerable:!1,writable:!1,value:e})}function $o(n){return n[ru]}function P_(n){return $o(n)!==void 0}function Zo(n,e=0,t=n.length-1){let i=n.subarray(e,t),s=$o(n);if(s){let r=[];for(let o of s)if(o[0]>=e&&o[0]+o[1]<=t){let a=[...o];a[0]-=e,r.push(a)}r.length&&ep(i,r)}return i}function sl(n){let e=Math.ceil(n.length/2),t=new Uint8Array(e);e--;for(let i=n.length,s=i-2;i>=0;i=s,s-=2,e--)t[e]=parseInt(n.substring(s,i),16);return t}function Dn(n){return n.reduce((e,t)=>e+t.toString(16).padStart(2,"0"),"")}function tp(n){let e=n.reduce((o,a)=>o+a.length,0),t=n.some(o=>P_(o)),i=[],s=new Uint8Array(e),r=0;for(let o of n){if(!(o instanceof Uint8Array))throw new TypeError(`Invalid array: ${o}`);if(s.set(o,r),t){let a=o[ru]??[[0,o.length]];for(let l of a)l[0]+=r;i.push(...a)}r+=o.length}return t&&ep(s,i),s}function Ko(n){let e=atob(n);return Uint8Array.from(e,t=>t.codePointAt(0))}var L_={"-":"+",_:"/"};function np(n){let e=n.replace(/[_-]/g,t=>L_[t]);return Ko(e.padEnd(Math.ceil(e.length/4)*4,"="))}function ip(){let n=new Uint8Array(4),e=new Uint32Array(n.buffer);return!((e[0]=1)&n[0])}function ou(n){let e="";for(let t of n){let i=t.codePointAt(0)?.toString(16).padStart(4,"0");e&&(e+=", "),e+=`U+${i}`}return e}var Jo=class{#e=new Map;registerEncoder(e,t){let i=this.#e.get(e);return this.#e.set(e,t),i}get(e){return this.#e.get(e)}delete(e){return this.#e.delete(e)}clear(){this.#e.clear()}};function rl(n,e){let[t,i,s]=n,[r,o,a]=e,l=Math.min(s.length,a.length);for(let c=0;c<l;c++){let h=s[c]-a[c];if(h!==0)return h}return 0}var qr=class n{static defaultOptions={chunkSize:4096};#e;#t=[];#n=null;#i=0;#s=0;constructor(e={}){if(this.#e={...n.defaultOptions,...e},this.#e.chunkSize<8)throw new RangeError(`Expected size >= 8, got ${this.#e.chunkSize}`);this.#r()}get length(){return this.#s}read(){this.#l();let e=new Uint8Array(this.#s),t=0;for(let i of this.#t)e.set(i,t),t+=i.length;return this.#r(),e}write(e){let t=e.length;t>this.#c()?(this.#l(),t>this.#e.chunkSize?(this.#t.push(e),this.#r()):(this.#r(),this.#t[this.#t.length-1].set(e),this.#i=t)):(this.#t[this.#t.length-1].set(e,this.#i),this.#i+=t),this.#s+=t}writeUint8(e){this.#o(1),this.#n.setUint8(this.#i,e),this.#a(1)}writeUint16(e,t=!1){this.#o(2),this.#n.setUint16(this.#i,e,t),this.#a(2)}writeUint32(e,t=!1){this.#o(4),this.#n.setUint32(this.#i,e,t),this.#a(4)}writeBigUint64(e,t=!1){this.#o(8),this.#n.setBigUint64(this.#i,e,t),this.#a(8)}writeInt16(e,t=!1){this.#o(2),this.#n.setInt16(this.#i,e,t),this.#a(2)}writeInt32(e,t=!1){this.#o(4),this.#n.setInt32(this.#i,e,t),this.#a(4)}writeBigInt64(e,t=!1){this.#o(8),this.#n.setBigInt64(this.#i,e,t),this.#a(8)}writeFloat32(e,t=!1){this.#o(4),this.#n.setFloat32(this.#i,e,t),this.#a(4)}writeFloat64(e,t=!1){this.#o(8),this.#n.setFloat64(this.#i,e,t),this.#a(8)}clear(){this.#s=0,this.#t=[],this.#r()}#r(){let e=new Uint8Array(this.#e.chunkSize);this.#t.push(e),this.#i=0,this.#n=new DataView(e.buffer,e.byteOffset,e.byteLength)}#l(){if(this.#i===0){this.#t.pop();return}let e=this.#t.length-1;this.#t[e]=this.#t[e].subarray(0,this.#i),this.#i=0,this.#n=null}#c(){let e=this.#t.length-1;return this.#t[e].length-this.#i}#o(e){this.#c()<e&&(this.#l(),this.#r())}#a(e){this.#i+=e,this.#s+=e}};var au=1n<<15n,jo=0b11111n<<10n,hp=1n<<9n,up=hp-1n,sp=hp|up,lu=1n<<31n,Qo=0b11111111n<<23n,fp=1n<<22n,dp=fp-1n,rp=fp|dp,ol=1n<<63n,hs=0b11111111111n<<52n,ea=1n<<51n,al=ea-1n,op=ea|al,ap=al-(up<<42n),lp=al-(dp<<29n),N_={2:"0b",8:"0o",16:"0x"},pp=(n=>(n[n.NATURAL=-2]="NATURAL",n[n.UNKNOWN=-1]="UNKNOWN",n[n.F16=2]="F16",n[n.F32=4]="F32",n[n.F64=8]="F64",n))(pp||{});function cp(n,e,t,i){let s="nan'";return n.quiet||(s+="!"),n.sign===-1&&(s+="-"),s+=i(Math.abs(n.payload),t),s+="'",s+=n.encodingIndicator,s}var ta=class extends Number{#e;#t=-1;constructor(e,t=!0,i=-1){super(NaN);let s=e;if(typeof e=="number"){if(!Number.isSafeInteger(e))throw new Error(`Invalid NAN payload: ${e}`);e=BigInt(e);let r=0n;if(e<0&&(r=ol,e=-e),e>=ea)throw new Error(`Payload too large: ${s}`);let o=t?ea:0n;switch(this.#e=r|hs|o|e,i){case-2:throw new Error("NAN_SIZE.NATURAL only valid for bigint constructor");case-1:i=this.preferredSize;break;case 2:if(this.#e&ap)throw new Error("Invalid size for payload");break;case 4:if(this.#e&lp)throw new Error("Invalid size for payload");break;case 8:break;default:throw new Error(`Invalid size: ${i}`)}this.#t=i}else if(typeof e=="bigint"){let r=-1;if((e&hs)===hs)this.#e=e,r=8;else if((e&Qo)===Qo){let o=(e&lu)<<32n;this.#e=o|hs|(e&rp)<<29n,r=4}else if((e&jo)===jo){let o=(e&au)<<48n;this.#e=o|hs|(e&sp)<<42n,r=2}else throw new Error(`Invalid raw NaN value: ${e}`);if(i===-1)this.#t=this.preferredSize;else if(i===-2)this.#t=r;else{if(i<r)throw new Error("Invalid bigint NaN size");this.#t=i}}else{let r=new DataView(e.buffer,e.byteOffset,e.byteLength);switch(e.length){case 3:{if(e[0]!==249)throw new Error("Invalid CBOR encoding for half float");let o=BigInt(r.getUint16(1,!1));if((o&jo)!==jo)throw new Error("Not a NaN");let a=(o&au)<<48n;this.#e=a|hs|(o&sp)<<42n,this.#t=2;break}case 5:{if(e[0]!==250)throw new Error("Invalid CBOR encoding for single float");let o=BigInt(r.getUint32(1,!1));if((o&Qo)!==Qo)throw new Error("Not a NaN");let a=(o&lu)<<32n;this.#e=a|hs|(o&rp)<<29n,this.#t=4;break}case 9:{if(e[0]!==251)throw new Error("Invalid CBOR encoding for double float");if(this.#e=r.getBigUint64(1,!1),(this.#e&hs)!==hs)throw new Error("Not a NaN (NaNaN)");this.#t=8;break}default:throw new RangeError(`Invalid NAN size (should be 2, 4, or 8): ${e.length-1}`)}}if(!this.payload&&!this.quiet)throw new Error("Signalling NaN with zero payload")}get bytes(){let e=new ArrayBuffer(this.#t+1),t=new DataView(e);switch(this.#t){case 2:{t.setUint8(0,249);let i=(this.#e&ol?au:0n)|jo|(this.#e&op)>>42n;t.setUint16(1,Number(i),!1);break}case 4:{t.setUint8(0,250);let i=(this.#e&ol?lu:0n)|Qo|(this.#e&op)>>29n;t.setUint32(1,Number(i),!1);break}case 8:t.setUint8(0,251),t.setBigUint64(1,this.#e);break}return new Uint8Array(e)}get quiet(){return!!(this.#e&ea)}get sign(){return this.#e&ol?-1:1}get payload(){return Number(this.#e&al)*this.sign}get raw(){return this.#e}get encodingIndicator(){switch(this.#t){case 2:return"_1";case 4:return"_2"}return"_3"}get size(){return this.#t}get preferredSize(){return(this.#e&ap)===0n?2:(this.#e&lp)===0n?4:8}get isShortestEncoding(){return this.preferredSize===this.#t}toCBOR(e){e.write(this.bytes)}toString(e=10){return cp(this,1,{},t=>(N_[e]??"")+t.toString(e))}[Symbol.for("nodejs.util.inspect.custom")](e,t,i){return cp(this,e,t,i)}};function cu(n,e=0,t=!1){let i=n[e]&128?-1:1,s=(n[e]&124)>>2,r=(n[e]&3)<<8|n[e+1];if(s===0){if(t&&r!==0)throw new Error(`Unwanted subnormal: ${i*5960464477539063e-23*r}`);return i*5960464477539063e-23*r}else if(s===31)return r?NaN:i*(1/0);return i*2**(s-25)*(1024+r)}function ll(n){let e=new DataView(new ArrayBuffer(4));e.setFloat32(0,n,!1);let t=e.getUint32(0,!1);if((t&8191)!==0)return null;let i=t>>16&32768,s=t>>23&255,r=t&8388607;if(!(s===0&&r===0))if(s>=113&&s<=142)i+=(s-112<<10)+(r>>13);else if(s>=103&&s<113){if(r&(1<<126-s)-1)return null;i+=r+8388608>>126-s}else if(s===255)i|=31744,i|=r>>13;else return null;return i}function mp(n){if(n!==0){let e=new ArrayBuffer(8),t=new DataView(e);t.setFloat64(0,n,!1);let i=t.getBigUint64(0,!1);if((i&0x7ff0000000000000n)===0n)return i&0x8000000000000000n?-0:0}return n}function gp(n){switch(n.length){case 2:cu(n,0,!0);break;case 4:{let e=new DataView(n.buffer,n.byteOffset,n.byteLength),t=e.getUint32(0,!1);if((t&2139095040)===0&&t&8388607)throw new Error(`Unwanted subnormal: ${e.getFloat32(0,!1)}`);break}case 8:{let e=new DataView(n.buffer,n.byteOffset,n.byteLength),t=e.getBigUint64(0,!1);if((t&0x7ff0000000000000n)===0n&&t&0x000fffffffffffn)throw new Error(`Unwanted subnormal: ${e.getFloat64(0,!1)}`);break}default:throw new TypeError(`Bad input to isSubnormal: ${n}`)}}var na=class extends TypeError{code="ERR_ENCODING_INVALID_ENCODED_DATA";constructor(){super("The encoded data was not valid for encoding wtf-8")}},cl=class extends RangeError{code="ERR_ENCODING_NOT_SUPPORTED";constructor(e){super(`Invalid encoding: "${e}"`)}};var hl=new Uint8Array(0);var hu=55296,_p=56320,xp=65533,ul="wtf-8";function U_(n){return n&&typeof n=="object"&&!(n instanceof ArrayBuffer)&&!(n instanceof SharedArrayBuffer)&&n.buffer instanceof ArrayBuffer}function O_(n){return n?n instanceof Uint8Array?n:U_(n)?new Uint8Array(n.buffer,n.byteOffset,n.byteLength):new Uint8Array(n):hl}var F_=[0,0,0,0,0,0,0,0,-1,-1,-1,-1,1,1,2,3],fr=class n{static DEFAULT_BUFFERSIZE=4096;encoding=ul;fatal;ignoreBOM;bufferSize;#e=0;#t=0;#n=0;#i=!0;#s;constructor(e="wtf8",t=void 0){if(e.toLowerCase().replace("-","")!=="wtf8")throw new cl(e);if(this.fatal=!!t?.fatal,this.ignoreBOM=!!t?.ignoreBOM,this.bufferSize=Math.floor(t?.bufferSize??n.DEFAULT_BUFFERSIZE),isNaN(this.bufferSize)||this.bufferSize<1)throw new RangeError(`Invalid buffer size: ${t?.bufferSize}`);this.#s=new Uint16Array(this.bufferSize)}decode(e,t){let i=!!t?.stream,s=O_(e),r=[],o=this.#s,a=this.bufferSize-3,l=0,c=()=>{if(this.#t=0,this.#e=0,this.#n=0,this.fatal)throw new na;o[l++]=xp},h=()=>{let u=this.#n;for(let p=0;p<u;p++)c()},f=u=>{if(this.#e===0)switch(F_[u>>4]){case-1:c();break;case 0:o[l++]=u;break;case 1:this.#t=u&31,(this.#t&30)===0?c():(this.#e=1,this.#n=1);break;case 2:this.#t=u&15,this.#e=2,this.#n=1;break;case 3:u&8?c():(this.#t=u&7,this.#e=3,this.#n=1);break}else{if((u&192)!==128||this.#n===1&&this.#e===2&&this.#t===0&&(u&32)===0||this.#e===3&&this.#t===0&&(u&48)===0)return h(),f(u);if(this.#t=this.#t<<6|u&63,this.#n++,--this.#e===0){if(this.ignoreBOM||!this.#i||this.#t!==65279)if(this.#t<65536)o[l++]=this.#t;else{let p=this.#t-65536;o[l++]=p>>>10&1023|hu,o[l++]=p&1023|_p}this.#t=0,this.#n=0,this.#i=!1}}};for(let u of s)l>=a&&(r.push(String.fromCharCode.apply(null,o.subarray(0,l))),l=0),f(u);return i||(this.#i=!0,(this.#t||this.#e)&&h()),l>0&&r.push(String.fromCharCode.apply(null,o.subarray(0,l))),r.join("")}};function B_(n){let e=0;for(let t of n){let i=t.codePointAt(0);i<128?e++:i<2048?e+=2:i<65536?e+=3:e+=4}return e}var Yr=class{encoding=ul;encode(e){if(!e)return hl;let t=new Uint8Array(B_(String(e)));return this.encodeInto(e,t),t}encodeInto(e,t){let i=String(e),s=i.length,r=t.length,o=0,a=0;for(a=0;a<s;a++){let l=i.codePointAt(a);if(l<128){if(o>=r)break;t[o++]=l}else if(l<2048){if(o>=r-1)break;t[o++]=192|l>>6,t[o++]=128|l&63}else if(l<65536){if(o>=r-2)break;t[o++]=224|l>>12,t[o++]=128|l>>6&63,t[o++]=128|l&63}else{if(o>=r-3)break;t[o++]=240|l>>18,t[o++]=128|l>>12&63,t[o++]=128|l>>6&63,t[o++]=128|l&63,a++}}return{read:a,written:o}}};var{ENCODED:VT}=Kt,yp=_e.SIMPLE_FLOAT<<5|ct.TWO,k_=_e.SIMPLE_FLOAT<<5|ct.FOUR,z_=_e.SIMPLE_FLOAT<<5|ct.EIGHT,G_=_e.SIMPLE_FLOAT<<5|Yi.TRUE,H_=_e.SIMPLE_FLOAT<<5|Yi.FALSE,V_=_e.SIMPLE_FLOAT<<5|Yi.UNDEFINED,W_=_e.SIMPLE_FLOAT<<5|Yi.NULL,X_=new TextEncoder,q_=new Yr,dl={...qr.defaultOptions,avoidInts:!1,cde:!1,collapseBigInts:!0,dateTag:wt.DATE_EPOCH,dcbor:!1,float64:!1,flushToZero:!1,forceEndian:null,ignoreOriginalEncoding:!1,largeNegativeAsBigInt:!1,reduceUnsafeNumbers:!1,rejectBigInts:!1,rejectCustomSimples:!1,rejectDuplicateKeys:!1,rejectFloats:!1,rejectUndefined:!1,simplifyNegativeZero:!1,sortKeys:null,stringNormalization:null,types:null,wtf8:!1,ignoreGlobalTags:!1},fu={cde:!0,ignoreOriginalEncoding:!0,sortKeys:rl},vp={...fu,dcbor:!0,largeNegativeAsBigInt:!0,reduceUnsafeNumbers:!0,rejectCustomSimples:!0,rejectDuplicateKeys:!0,rejectUndefined:!0,simplifyNegativeZero:!0,stringNormalization:"NFC"};function Sp(n){let e=n<0;return typeof n=="bigint"?[e?-n-1n:n,e]:[e?-n-1:n,e]}function uu(n,e,t){if(t.rejectFloats)throw new Error(`Attempt to encode an unwanted floating point number: ${n}`);if(isNaN(n))e.writeUint8(yp),e.writeUint16(32256);else if(!t.float64&&Math.fround(n)===n){let i=ll(n);i===null?(e.writeUint8(k_),e.writeFloat32(n)):(e.writeUint8(yp),e.writeUint16(i))}else e.writeUint8(z_),e.writeFloat64(n)}function Zn(n,e,t){let[i,s]=Sp(n);if(s&&t)throw new TypeError(`Negative size: ${n}`);t??=s?_e.NEG_INT:_e.POS_INT,t<<=5,i<24?e.writeUint8(t|i):i<=255?(e.writeUint8(t|ct.ONE),e.writeUint8(i)):i<=65535?(e.writeUint8(t|ct.TWO),e.writeUint16(i)):i<=4294967295?(e.writeUint8(t|ct.FOUR),e.writeUint32(i)):(e.writeUint8(t|ct.EIGHT),e.writeBigUint64(BigInt(i)))}function dr(n,e,t){typeof n=="number"?Zn(n,e,_e.TAG):typeof n=="object"&&!t.ignoreOriginalEncoding&&Kt.ENCODED in n?e.write(n[Kt.ENCODED]):n<=Number.MAX_SAFE_INTEGER?Zn(Number(n),e,_e.TAG):(e.writeUint8(_e.TAG<<5|ct.EIGHT),e.writeBigUint64(BigInt(n)))}function bp(n,e,t){let[i,s]=Sp(n);if(t.collapseBigInts&&(!t.largeNegativeAsBigInt||n>=-0x8000000000000000n)){if(i<=0xffffffffn){Zn(Number(n),e);return}if(i<=0xffffffffffffffffn){let c=(s?_e.NEG_INT:_e.POS_INT)<<5;e.writeUint8(c|ct.EIGHT),e.writeBigUint64(i);return}}if(t.rejectBigInts)throw new Error(`Attempt to encode unwanted bigint: ${n}`);let r=s?wt.NEG_BIGINT:wt.POS_BIGINT,o=i.toString(16),a=o.length%2?"0":"";dr(r,e,t);let l=sl(a+o);Zn(l.length,e,_e.BYTE_STRING),e.write(l)}function Y_(n,e,t){t.flushToZero&&(n=mp(n)),Object.is(n,-0)?t.simplifyNegativeZero?t.avoidInts?uu(0,e,t):Zn(0,e):uu(n,e,t):!t.avoidInts&&Number.isSafeInteger(n)?Zn(n,e):t.reduceUnsafeNumbers&&Math.floor(n)===n&&n>=Xr.MIN&&n<=Xr.MAX?bp(BigInt(n),e,t):uu(n,e,t)}function Mp(n,e,t){let i=t.stringNormalization?n.normalize(t.stringNormalization):n;if(t.wtf8&&!n.isWellFormed()){let s=q_.encode(i);dr(wt.WTF8,e,t),Zn(s.length,e,_e.BYTE_STRING),e.write(s)}else{let s=X_.encode(i);Zn(s.length,e,_e.UTF8_STRING),e.write(s)}}function $_(n,e,t){let i=n;pl(i,i.length,_e.ARRAY,e,t);for(let s of i)Os(s,e,t)}function Z_(n,e){Zn(n.length,e,_e.BYTE_STRING),e.write(n)}var fl=new Jo;fl.registerEncoder(Array,$_),fl.registerEncoder(Uint8Array,Z_);function nn(n,e){return fl.registerEncoder(n,e)}function pl(n,e,t,i,s){let r=Qd(n);r&&!s.ignoreOriginalEncoding?i.write(r):Zn(e,i,t)}function K_(n,e,t){if(n===null){e.writeUint8(W_);return}if(!t.ignoreOriginalEncoding&&Kt.ENCODED in n){e.write(n[Kt.ENCODED]);return}let i=n.constructor;if(i){let r=t.types?.get(i)??(t.ignoreGlobalTags?void 0:fl.get(i));if(r){let o=r(n,e,t);if(o!==void 0){if(!Array.isArray(o)||o.length!==2)throw new Error("Invalid encoder return value");(typeof o[0]=="bigint"||isFinite(Number(o[0])))&&dr(o[0],e,t),Os(o[1],e,t)}return}}if(typeof n.toCBOR=="function"){let r=n.toCBOR(e,t);r&&((typeof r[0]=="bigint"||isFinite(Number(r[0])))&&dr(r[0],e,t),Os(r[1],e,t));return}if(typeof n.toJSON=="function"){Os(n.toJSON(),e,t);return}let s=Object.entries(n).map(r=>[r[0],r[1],Fs(r[0],t)]);t.sortKeys&&s.sort(t.sortKeys),pl(n,s.length,_e.MAP,e,t);for(let[r,o,a]of s)e.write(a),Os(o,e,t)}function J_(n,e,t){if(!n.description||n!==Symbol.for(n.description))throw new TypeError(`Private or empty symbol: ${n.toString()}`);dr(280,e,t),Mp(n.description,e,t)}function Os(n,e,t){switch(typeof n){case"number":Y_(n,e,t);break;case"bigint":bp(n,e,t);break;case"string":Mp(n,e,t);break;case"boolean":e.writeUint8(n?G_:H_);break;case"undefined":if(t.rejectUndefined)throw new Error("Attempt to encode unwanted undefined.");e.writeUint8(V_);break;case"object":K_(n,e,t);break;case"symbol":J_(n,e,t);break;default:throw new TypeError(`Unknown type: ${typeof n}, ${String(n)}`)}}function Fs(n,e={}){let t={...dl};e.dcbor?Object.assign(t,vp):e.cde&&Object.assign(t,fu),Object.assign(t,e);let i=new qr(t);return Os(n,i,t),i.read()}var pr=(n=>(n[n.NEVER=-1]="NEVER",n[n.PREFERRED=0]="PREFERRED",n[n.ALWAYS=1]="ALWAYS",n))(pr||{});var Ai=class n{static KnownSimple=new Map([[Yi.FALSE,!1],[Yi.TRUE,!0],[Yi.NULL,null],[Yi.UNDEFINED,void 0]]);value;constructor(e){this.value=e}static create(e){return n.KnownSimple.has(e)?n.KnownSimple.get(e):new n(e)}toCBOR(e,t){if(t.rejectCustomSimples)throw new Error(`Cannot encode non-standard Simple value: ${this.value}`);Zn(this.value,e,_e.SIMPLE_FLOAT)}toString(){return`simple(${this.value})`}decode(){return n.KnownSimple.has(this.value)?n.KnownSimple.get(this.value):this}[Symbol.for("nodejs.util.inspect.custom")](e,t,i){return`simple(${i(this.value,t)})`}};var j_=new TextDecoder("utf8",{fatal:!0,ignoreBOM:!0}),$i=class n{static defaultOptions={maxDepth:1024,encoding:"hex",requirePreferred:!1};#e;#t;#n=0;#i;constructor(e,t){if(this.#i={...n.defaultOptions,...t},typeof e=="string")switch(this.#i.encoding){case"hex":this.#e=sl(e);break;case"base64":this.#e=Ko(e);break;default:throw new TypeError(`Encoding not implemented: "${this.#i.encoding}"`)}else this.#e=e;this.#t=new DataView(this.#e.buffer,this.#e.byteOffset,this.#e.byteLength)}toHere(e){return Zo(this.#e,e,this.#n)}*[Symbol.iterator](){if(yield*this.#s(0),this.#n!==this.#e.length)throw new Error("Extra data in input")}*seq(){for(;this.#n<this.#e.length;)yield*this.#s(0)}*#s(e){if(e++>this.#i.maxDepth)throw new Error(`Maximum depth ${this.#i.maxDepth} exceeded`);let t=this.#n,i=this.#t.getUint8(this.#n++),s=i>>5,r=i&31,o=r,a=!1,l=0;switch(r){case ct.ONE:if(l=1,o=this.#t.getUint8(this.#n),s===_e.SIMPLE_FLOAT){if(o<32)throw new Error(`Invalid simple encoding in extra byte: ${o}`);a=!0}else if(this.#i.requirePreferred&&o<24)throw new Error(`Unexpectedly long integer encoding (1) for ${o}`);break;case ct.TWO:if(l=2,s===_e.SIMPLE_FLOAT)o=cu(this.#e,this.#n);else if(o=this.#t.getUint16(this.#n,!1),this.#i.requirePreferred&&o<=255)throw new Error(`Unexpectedly long integer encoding (2) for ${o}`);break;case ct.FOUR:if(l=4,s===_e.SIMPLE_FLOAT)o=this.#t.getFloat32(this.#n,!1);else if(o=this.#t.getUint32(this.#n,!1),this.#i.requirePreferred&&o<=65535)throw new Error(`Unexpectedly long integer encoding (4) for ${o}`);break;case ct.EIGHT:{if(l=8,s===_e.SIMPLE_FLOAT)o=this.#t.getFloat64(this.#n,!1);else if(o=this.#t.getBigUint64(this.#n,!1),o<=Number.MAX_SAFE_INTEGER&&(o=Number(o)),this.#i.requirePreferred&&o<=4294967295)throw new Error(`Unexpectedly long integer encoding (8) for ${o}`);break}case 28:case 29:case 30:throw new Error(`Additional info not implemented: ${r}`);case ct.INDEFINITE:switch(s){case _e.POS_INT:case _e.NEG_INT:case _e.TAG:throw new Error(`Invalid indefinite encoding for MT ${s}`);case _e.SIMPLE_FLOAT:yield[s,r,Kt.BREAK,t,0];return}o=1/0;break;default:a=!0}switch(this.#n+=l,s){case _e.POS_INT:yield[s,r,o,t,l];break;case _e.NEG_INT:yield[s,r,typeof o=="bigint"?-1n-o:-1-Number(o),t,l];break;case _e.BYTE_STRING:o===1/0?yield*this.#l(s,e,t):yield[s,r,this.#r(o),t,o];break;case _e.UTF8_STRING:o===1/0?yield*this.#l(s,e,t):yield[s,r,j_.decode(this.#r(o)),t,o];break;case _e.ARRAY:if(o===1/0)yield*this.#l(s,e,t,!1);else{let c=Number(o);yield[s,r,c,t,l];for(let h=0;h<c;h++)yield*this.#s(e+1)}break;case _e.MAP:if(o===1/0)yield*this.#l(s,e,t,!1);else{let c=Number(o);yield[s,r,c,t,l];for(let h=0;h<c;h++)yield*this.#s(e),yield*this.#s(e)}break;case _e.TAG:yield[s,r,o,t,l],yield*this.#s(e);break;case _e.SIMPLE_FLOAT:{let c=o;a&&(o=Ai.create(Number(o))),yield[s,r,o,t,c];break}}}#r(e){let t=Zo(this.#e,this.#n,this.#n+=e);if(t.length!==e)throw new Error(`Unexpected end of stream reading ${e} bytes, got ${t.length}`);return t}*#l(e,t,i,s=!0){for(yield[e,ct.INDEFINITE,1/0,i,1/0];;){let r=this.#s(t),o=r.next(),[a,l,c]=o.value;if(c===Kt.BREAK){yield o.value,r.next();return}if(s){if(a!==e)throw new Error(`Unmatched major type.  Expected ${e}, got ${a}.`);if(l===ct.INDEFINITE)throw new Error("New stream started in typed stream")}yield o.value,yield*r}}};var Q_=new Map([[ct.ZERO,1],[ct.ONE,2],[ct.TWO,3],[ct.FOUR,5],[ct.EIGHT,9]]),ex=new Uint8Array(0);function tx(n,e){return!e.boxed&&!e.preferMap&&n.every(([t])=>typeof t=="string")?Object.fromEntries(n):new Map(n)}var gn=class n{static defaultDecodeOptions={...$i.defaultOptions,ParentType:n,boxed:!1,cde:!1,dcbor:!1,diagnosticSizes:pr.PREFERRED,collapseBigInts:!1,convertUnsafeIntsToFloat:!1,createObject:tx,keepNanPayloads:!1,pretty:!1,preferBigInt:!1,preferMap:!1,rejectLargeNegatives:!1,rejectBigInts:!1,rejectDuplicateKeys:!1,rejectFloats:!1,rejectInts:!1,rejectLongLoundNaN:!1,rejectLongFloats:!1,rejectNegativeZero:!1,rejectSimple:!1,rejectStreaming:!1,rejectStringsNotNormalizedAs:null,rejectSubnormals:!1,rejectUndefined:!1,rejectUnsafeFloatInts:!1,saveOriginal:!1,sortKeys:null,tags:null,ignoreGlobalTags:!1};static cdeDecodeOptions={cde:!0,rejectStreaming:!0,requirePreferred:!0,sortKeys:rl};static dcborDecodeOptions={...this.cdeDecodeOptions,dcbor:!0,convertUnsafeIntsToFloat:!0,rejectDuplicateKeys:!0,rejectLargeNegatives:!0,rejectLongLoundNaN:!0,rejectLongFloats:!0,rejectNegativeZero:!0,rejectSimple:!0,rejectUndefined:!0,rejectUnsafeFloatInts:!0,rejectStringsNotNormalizedAs:"NFC"};parent;mt;ai;left;offset;count=0;children=[];depth=0;#e;#t=null;constructor(e,t,i,s){if([this.mt,this.ai,,this.offset]=e,this.left=t,this.parent=i,this.#e=s,i&&(this.depth=i.depth+1),this.mt===_e.MAP&&(this.#e.sortKeys||this.#e.rejectDuplicateKeys)&&(this.#t=[]),this.#e.rejectStreaming&&this.ai===ct.INDEFINITE)throw new Error("Streaming not supported")}get isStreaming(){return this.left===1/0}get done(){return this.left===0}static create(e,t,i,s){let[r,o,a,l]=e;switch(r){case _e.POS_INT:case _e.NEG_INT:{if(i.rejectInts)throw new Error(`Unexpected integer: ${a}`);if(i.rejectLargeNegatives&&a<-0x8000000000000000n)throw new Error(`Invalid 65bit negative number: ${a}`);let c=a;return i.preferBigInt?c=BigInt(c):i.convertUnsafeIntsToFloat&&c>=Xr.MIN&&c<=Xr.MAX&&(c=Number(a)),i.boxed?Us(c,s.toHere(l)):c}case _e.SIMPLE_FLOAT:if(o>ct.ONE){if(typeof a=="symbol")return a;if(i.rejectFloats)throw new Error(`Decoding unwanted floating point number: ${a}`);if(i.rejectNegativeZero&&Object.is(a,-0))throw new Error("Decoding negative zero");if(isNaN(a)){let c=s.toHere(l),h=new ta(c);if(i.rejectLongLoundNaN){if(h.payload||c.length>3)throw new Error(`Invalid NaN encoding: "${Dn(c)}"`)}else if(i.keepNanPayloads&&(h.payload||h.sign===-1)){if(i.rejectLongFloats&&!h.isShortestEncoding)throw new Error(`NaN should have been encoded shorter: ${a}`);return h}}if(i.rejectSubnormals&&gp(s.toHere(l+1)),i.rejectLongFloats){let c=Fs(a,{chunkSize:9,reduceUnsafeNumbers:i.rejectUnsafeFloatInts});if(c[0]>>5!==r)throw new Error(`Should have been encoded as int, not float: ${a}`);if(c.length<Q_.get(o))throw new Error(`Number should have been encoded shorter: ${a}`)}if(typeof a=="number"&&i.boxed)return Us(a,s.toHere(l))}else{if(i.rejectSimple&&a instanceof Ai)throw new Error(`Invalid simple value: ${a}`);if(i.rejectUndefined&&a===void 0)throw new Error("Unexpected undefined")}return a;case _e.BYTE_STRING:case _e.UTF8_STRING:if(a===1/0)return new i.ParentType(e,1/0,t,i);if(i.rejectStringsNotNormalizedAs&&typeof a=="string"){let c=a.normalize(i.rejectStringsNotNormalizedAs);if(a!==c)throw new Error(`String not normalized as "${i.rejectStringsNotNormalizedAs}", got [${ou(a)}] instead of [${ou(c)}]`)}return i.boxed?Us(a,s.toHere(l)):a;case _e.ARRAY:return new i.ParentType(e,a,t,i);case _e.MAP:return new i.ParentType(e,a*2,t,i);case _e.TAG:{let c=new i.ParentType(e,1,t,i);return c.children=new Qe(a),c}}throw new TypeError(`Invalid major type: ${r}`)}static decodeToEncodeOpts(e){return{...dl,avoidInts:e.rejectInts,float64:!e.rejectLongFloats,flushToZero:e.rejectSubnormals,largeNegativeAsBigInt:e.rejectLargeNegatives,sortKeys:e.sortKeys}}push(e,t,i){if(this.children.push(e),this.#t){let s=Ns(e)||t.toHere(i);this.#t.push(s)}return--this.left}replaceLast(e,t,i){let s,r=-1/0;if(this.children instanceof Qe?(r=0,s=this.children.contents,this.children.contents=e):(r=this.children.length-1,s=this.children[r],this.children[r]=e),this.#t){let o=Ns(e)||i.toHere(t.offset);this.#t[r]=o}return s}convert(e){let t;switch(this.mt){case _e.ARRAY:t=this.children;break;case _e.MAP:{let i=this.#n();if(this.#e.sortKeys){let s;for(let r of i){if(s&&this.#e.sortKeys(s,r)>=0)throw new Error(`Duplicate or out of order key: "0x${r[2]}"`);s=r}}else if(this.#e.rejectDuplicateKeys){let s=new Set;for(let[r,o,a]of i){let l=Dn(a);if(s.has(l))throw new Error(`Duplicate key: "0x${l}"`);s.add(l)}}t=this.#e.createObject(i,this.#e);break}case _e.BYTE_STRING:return tp(this.children);case _e.UTF8_STRING:{let i=this.children.join("");t=this.#e.boxed?Us(i,e.toHere(this.offset)):i;break}case _e.TAG:t=this.children.decode(this.#e);break;default:throw new TypeError(`Invalid mt on convert: ${this.mt}`)}return this.#e.saveOriginal&&t&&typeof t=="object"&&Ds(t,e.toHere(this.offset)),t}#n(){let e=this.children,t=e.length;if(t%2)throw new Error("Missing map value");let i=new Array(t/2);if(this.#t)for(let s=0;s<t;s+=2)i[s>>1]=[e[s],e[s+1],this.#t[s]];else for(let s=0;s<t;s+=2)i[s>>1]=[e[s],e[s+1],ex];return i}};var du="  ",nx=new TextEncoder,ml=class extends gn{close="";quote='"';get isEmptyStream(){return(this.mt===_e.UTF8_STRING||this.mt===_e.BYTE_STRING)&&this.count===0}};function Bs(n,e,t,i){let s="";if(e===ct.INDEFINITE)s+="_";else{if(i.diagnosticSizes===pr.NEVER)return"";{let r=i.diagnosticSizes===pr.ALWAYS;if(!r){let o=ct.ZERO;if(Object.is(t,-0))o=ct.TWO;else if(n===_e.POS_INT||n===_e.NEG_INT){let a=t<0,l=typeof t=="bigint"?1n:1,c=a?-t-l:t;c<=23?o=Number(c):c<=255?o=ct.ONE:c<=65535?o=ct.TWO:c<=4294967295?o=ct.FOUR:o=ct.EIGHT}else isFinite(t)?Math.fround(t)===t?ll(t)==null?o=ct.FOUR:o=ct.TWO:o=ct.EIGHT:o=ct.TWO;r=o!==e}r&&(s+="_",e<ct.ONE?s+="i":s+=String(e-24))}}return s}function pu(n,e){let t={...gn.defaultDecodeOptions,...e,ParentType:ml},i=new $i(n,t),s,r,o="";for(let a of i){let[l,c,h]=a;switch(s&&(s.count>0&&h!==Kt.BREAK&&(s.mt===_e.MAP&&s.count%2?o+=": ":(o+=",",t.pretty||(o+=" "))),t.pretty&&(s.mt!==_e.MAP||s.count%2===0)&&(o+=`
${du.repeat(s.depth+1)}`)),r=gn.create(a,s,t,i),l){case _e.POS_INT:case _e.NEG_INT:o+=String(h),o+=Bs(l,c,h,t);break;case _e.SIMPLE_FLOAT:if(h!==Kt.BREAK)if(typeof h=="number"){let f=Object.is(h,-0)?"-0.0":String(h);o+=f,isFinite(h)&&!/[.e]/.test(f)&&(o+=".0"),o+=Bs(l,c,h,t)}else h instanceof Ai?(o+="simple(",o+=String(h.value),o+=Bs(_e.POS_INT,c,h.value,t),o+=")"):o+=String(h);break;case _e.BYTE_STRING:h===1/0?(o+="(_ ",r.close=")",r.quote="'"):(o+="h'",o+=Dn(h),o+="'",o+=Bs(_e.POS_INT,c,h.length,t));break;case _e.UTF8_STRING:h===1/0?(o+="(_ ",r.close=")"):(o+=JSON.stringify(h),o+=Bs(_e.POS_INT,c,nx.encode(h).length,t));break;case _e.ARRAY:{o+="[";let f=Bs(_e.POS_INT,c,h,t);o+=f,f&&(o+=" "),t.pretty&&h?r.close=`
${du.repeat(r.depth)}]`:r.close="]";break}case _e.MAP:{o+="{";let f=Bs(_e.POS_INT,c,h,t);o+=f,f&&(o+=" "),t.pretty&&h?r.close=`
${du.repeat(r.depth)}}`:r.close="}";break}case _e.TAG:o+=String(h),o+=Bs(_e.POS_INT,c,h,t),o+="(",r.close=")";break}if(r===Kt.BREAK)if(s?.isStreaming)s.left=0;else throw new Error("Unexpected BREAK");else s&&(s.count++,s.left--);for(r instanceof ml&&(s=r);s?.done;){if(s.isEmptyStream)o=o.slice(0,-3),o+=`${s.quote}${s.quote}_`;else{if(s.mt===_e.MAP&&s.count%2!==0)throw new Error(`Odd streaming map size: ${s.count}`);o+=s.close}s=s.parent}}return o}var ix=new TextDecoder,sa=class extends gn{depth=0;leaf=!1;value;length;[Kt.ENCODED];constructor(e,t,i,s){super(e,t,i,s),this.parent?this.depth=this.parent.depth+1:this.depth=s.initialDepth,[,,this.value,,this.length]=e}numBytes(){switch(this.ai){case ct.ONE:return 1;case ct.TWO:return 2;case ct.FOUR:return 4;case ct.EIGHT:return 8}return 0}};function wp(n){return n instanceof sa}function gl(n,e){return n===1/0?"Indefinite":e?`${n} ${e}${n!==1&&n!==1n?"s":""}`:String(n)}function ia(n){return"".padStart(n," ")}function Ep(n,e,t){let i="";i+=ia(n.depth*2);let s=Ns(n);i+=Dn(s.subarray(0,1));let r=n.numBytes();r&&(i+=" ",i+=Dn(s.subarray(1,r+1))),i=i.padEnd(e.minCol+1," "),i+="-- ",t!==void 0&&(i+=ia(n.depth*2),t!==""&&(i+=`[${t}] `));let o=!1,[a]=n.children;switch(n.mt){case _e.POS_INT:i+=`Unsigned: ${a}`,typeof a=="bigint"&&(i+="n");break;case _e.NEG_INT:i+=`Negative: ${a}`,typeof a=="bigint"&&(i+="n");break;case _e.BYTE_STRING:i+=`Bytes (Length: ${gl(n.length)})`;break;case _e.UTF8_STRING:i+=`UTF8 (Length: ${gl(n.length)})`,n.length!==1/0&&(i+=`: ${JSON.stringify(a)}`);break;case _e.ARRAY:i+=`Array (Length: ${gl(n.value,"item")})`;break;case _e.MAP:i+=`Map (Length: ${gl(n.value,"pair")})`;break;case _e.TAG:{i+=`Tag #${n.value}`;let l=n.children,[c]=l.contents.children,h=new Qe(l.tag,c);Ds(h,s);let f=h.comment(e,n.depth);f&&(i+=": ",i+=f),o||=h.noChildren;break}case _e.SIMPLE_FLOAT:a===Kt.BREAK?i+="BREAK":n.ai>ct.ONE?Object.is(a,-0)?i+="Float: -0":i+=`Float: ${a}`:(i+="Simple: ",a instanceof Ai?i+=a.value:i+=a);break}if(!o)if(n.leaf){if(i+=`
`,s.length>r+1){let l=ia((n.depth+1)*2),c=$o(s);if(c?.length){c.sort((f,u)=>f[0]-u[0]||u[1]-f[1]);let h=0;for(let[f,u,p]of c)if(!(f<h)){if(h=f+u,p==="<<"){i+=ia(e.minCol+1),i+="--",i+=l,i+="<< ";let g=Zo(s,f,f+u),S=$o(g);if(S){let d=S.findIndex(([m,y,A])=>m===0&&y===u&&A==="<<");d>=0&&S.splice(d,1)}i+=pu(g),i+=` >>
`,i+=_l(g,{initialDepth:n.depth+1,minCol:e.minCol,noPrefixHex:!0});continue}else p==="'"&&(i+=ia(e.minCol+1),i+="--",i+=l,i+="'",i+=ix.decode(s.subarray(f,f+u)),i+=`'
`);if(f>r)for(let g=f;g<f+u;g+=8){let S=Math.min(g+8,f+u);i+=l,i+=Dn(s.subarray(g,S)),i+=`
`}}}else for(let h=r+1;h<s.length;h+=8)i+=l,i+=Dn(s.subarray(h,h+8)),i+=`
`}}else{i+=`
`;let l=0;for(let c of n.children){if(wp(c)){let h=String(l);n.mt===_e.MAP?h=l%2?`val ${(l-1)/2}`:`key ${l/2}`:n.mt===_e.TAG&&(h=""),i+=Ep(c,e,h)}l++}}return i}var sx={...gn.defaultDecodeOptions,initialDepth:0,noPrefixHex:!1,minCol:0};function _l(n,e){let t={...sx,...e,ParentType:sa,saveOriginal:!0},i=new $i(n,t),s,r;for(let a of i){if(r=gn.create(a,s,t,i),a[2]===Kt.BREAK)if(s?.isStreaming)s.left=1;else throw new Error("Unexpected BREAK");if(!wp(r)){let h=new sa(a,0,s,t);h.leaf=!0,h.children.push(r),Ds(h,i.toHere(a[3])),r=h}let l=(r.depth+1)*2,c=r.numBytes();for(c&&(l+=1,l+=c*2),t.minCol=Math.max(t.minCol,l),s&&s.push(r,i,a[3]),s=r;s?.done;)r=s,r.leaf||Ds(r,i.toHere(r.offset)),{parent:s}=s}e&&(e.minCol=t.minCol);let o=t.noPrefixHex?"":`0x${Dn(i.toHere(0))}
`;return o+=Ep(r,t),o}var Tp=!ip();function vl(n){if(typeof n=="object"&&n){if(n.constructor!==Number)throw new Error(`Expected number: ${n}`)}else if(typeof n!="number")throw new Error(`Expected number: ${n}`)}function us(n){if(typeof n=="object"&&n){if(n.constructor!==String)throw new Error(`Expected string: ${n}`)}else if(typeof n!="string")throw new Error(`Expected string: ${n}`)}function fs(n){if(!(n instanceof Uint8Array))throw new Error(`Expected Uint8Array: ${n}`)}function Lp(n){if(!Array.isArray(n))throw new Error(`Expected Array: ${n}`)}nn(Map,(n,e,t)=>{let i=[...n.entries()].map(s=>[s[0],s[1],Fs(s[0],t)]);if(t.rejectDuplicateKeys){let s=new Set;for(let[r,o,a]of i){let l=Dn(a);if(s.has(l))throw new Error(`Duplicate map key: 0x${l}`);s.add(l)}}t.sortKeys&&i.sort(t.sortKeys),pl(n,n.size,_e.MAP,e,t);for(let[s,r,o]of i)e.write(o),Os(r,e,t)});function mu(n){return us(n.contents),new Date(n.contents)}mu.comment=n=>{us(n.contents);let e=new Date(n.contents);return`(String ${n.tag===wt.DATE_FULL?"Full ":""}Date) ${e.toISOString()}`},Qe.registerDecoder(wt.DATE_STRING,mu),Qe.registerDecoder(wt.DATE_FULL,mu);function Ap(n){return vl(n.contents),new Date(n.contents*1e3)}Ap.comment=n=>(vl(n.contents),`(Epoch Date) ${new Date(n.contents*1e3).toISOString()}`),Qe.registerDecoder(wt.DATE_EPOCH,Ap);var xu=1e3*60*60*24;function Rp(n){return vl(n.contents),new Date(n.contents*xu)}Rp.comment=n=>(vl(n.contents),`(Epoch Date) ${new Date(n.contents*xu).toISOString()}`),Qe.registerDecoder(wt.DATE_EPOCH_DAYS,Rp),nn(Date,(n,e,t)=>{switch(t.dateTag){case wt.DATE_EPOCH:return[t.dateTag,n.valueOf()/1e3];case wt.DATE_STRING:return[t.dateTag,n.toISOString().replace(/\.000Z$/,"Z")];case wt.DATE_EPOCH_DAYS:return[t.dateTag,Math.floor(n.valueOf()/xu)];case wt.DATE_FULL:return[t.dateTag,n.toISOString().split("T")[0]];default:throw new Error(`Unsupported date tag: ${t.dateTag}`)}});function yl(n,e,t){if(fs(e.contents),t.rejectBigInts)throw new Error(`Decoding unwanted big integer: ${e}(h'${Dn(e.contents)}')`);if(t.requirePreferred&&e.contents[0]===0)throw new Error(`Decoding overly-large bigint: ${e.tag}(h'${Dn(e.contents)})`);let i=e.contents.reduce((r,o)=>r<<8n|BigInt(o),0n);n&&(i=-1n-i);let s=i>=Number.MIN_SAFE_INTEGER&&i<=Number.MAX_SAFE_INTEGER;if(t.requirePreferred&&s)throw new Error(`Decoding bigint that could have been int: ${i}n`);return t.collapseBigInts&&s&&(i=Number(i)),t.boxed?Us(i,e.contents):i}var Cp=yl.bind(null,!1),Ip=yl.bind(null,!0);Cp.comment=(n,e)=>`(Positive BigInt) ${yl(!1,n,e)}n`,Ip.comment=(n,e)=>`(Negative BigInt) ${yl(!0,n,e)}n`,Qe.registerDecoder(wt.POS_BIGINT,Cp),Qe.registerDecoder(wt.NEG_BIGINT,Ip);function gu(n,e){return fs(n.contents),n}gu.comment=(n,e,t)=>{fs(n.contents);let i={...e,initialDepth:t+2,noPrefixHex:!0},s=Ns(n),r=2**((s[0]&31)-24)+1,o=s[r]&31,a=Dn(s.subarray(r,++r));o>=24&&(a+=" ",a+=Dn(s.subarray(r,r+2**(o-24)))),i.minCol=Math.max(i.minCol,(t+1)*2+a.length);let l=_l(n.contents,i),c=`Embedded CBOR
`;return c+=`${"".padStart((t+1)*2," ")}${a}`.padEnd(i.minCol+1," "),c+=`-- Bytes (Length: ${n.contents.length})
`,c+=l,c},gu.noChildren=!0,Qe.registerDecoder(wt.CBOR,gu),Qe.registerDecoder(wt.URI,n=>(us(n.contents),new URL(n.contents)),"URI"),nn(URL,n=>[wt.URI,n.toString()]),Qe.registerDecoder(wt.BASE64URL,n=>(us(n.contents),np(n.contents)),"Base64url-encoded"),Qe.registerDecoder(wt.BASE64,n=>(us(n.contents),Ko(n.contents)),"Base64-encoded"),Qe.registerDecoder(35,n=>(us(n.contents),new RegExp(n.contents)),"RegExp"),Qe.registerDecoder(21065,n=>{us(n.contents);let e=`^(?:${n.contents})$`;return new RegExp(e,"u")},"I-RegExp"),Qe.registerDecoder(wt.REGEXP,n=>{if(Lp(n.contents),n.contents.length<1||n.contents.length>2)throw new Error(`Invalid RegExp Array: ${n.contents}`);return new RegExp(n.contents[0],n.contents[1])},"RegExp"),nn(RegExp,n=>[wt.REGEXP,[n.source,n.flags]]),Qe.registerDecoder(64,n=>(fs(n.contents),n.contents),"uint8 Typed Array");function On(n,e,t){fs(n.contents);let i=n.contents.length;if(i%e.BYTES_PER_ELEMENT!==0)throw new Error(`Number of bytes must be divisible by ${e.BYTES_PER_ELEMENT}, got: ${i}`);i/=e.BYTES_PER_ELEMENT;let s=new e(i),r=new DataView(n.contents.buffer,n.contents.byteOffset,n.contents.byteLength),o=r[`get${e.name.replace(/Array/,"")}`].bind(r);for(let a=0;a<i;a++)s[a]=o(a*e.BYTES_PER_ELEMENT,t);return s}function ks(n,e,t,i,s){let r=s.forceEndian??Tp;if(dr(r?e:t,n,s),Zn(i.byteLength,n,_e.BYTE_STRING),Tp===r)n.write(new Uint8Array(i.buffer,i.byteOffset,i.byteLength));else{let o=`write${i.constructor.name.replace(/Array/,"")}`,a=n[o].bind(n);for(let l of i)a(l,r)}}Qe.registerDecoder(65,n=>On(n,Uint16Array,!1),"uint16, big endian, Typed Array"),Qe.registerDecoder(66,n=>On(n,Uint32Array,!1),"uint32, big endian, Typed Array"),Qe.registerDecoder(67,n=>On(n,BigUint64Array,!1),"uint64, big endian, Typed Array"),Qe.registerDecoder(68,n=>(fs(n.contents),new Uint8ClampedArray(n.contents)),"uint8 Typed Array, clamped arithmetic"),nn(Uint8ClampedArray,n=>[68,new Uint8Array(n.buffer,n.byteOffset,n.byteLength)]),Qe.registerDecoder(69,n=>On(n,Uint16Array,!0),"uint16, little endian, Typed Array"),nn(Uint16Array,(n,e,t)=>ks(e,69,65,n,t)),Qe.registerDecoder(70,n=>On(n,Uint32Array,!0),"uint32, little endian, Typed Array"),nn(Uint32Array,(n,e,t)=>ks(e,70,66,n,t)),Qe.registerDecoder(71,n=>On(n,BigUint64Array,!0),"uint64, little endian, Typed Array"),nn(BigUint64Array,(n,e,t)=>ks(e,71,67,n,t)),Qe.registerDecoder(72,n=>(fs(n.contents),new Int8Array(n.contents)),"sint8 Typed Array"),nn(Int8Array,n=>[72,new Uint8Array(n.buffer,n.byteOffset,n.byteLength)]),Qe.registerDecoder(73,n=>On(n,Int16Array,!1),"sint16, big endian, Typed Array"),Qe.registerDecoder(74,n=>On(n,Int32Array,!1),"sint32, big endian, Typed Array"),Qe.registerDecoder(75,n=>On(n,BigInt64Array,!1),"sint64, big endian, Typed Array"),Qe.registerDecoder(77,n=>On(n,Int16Array,!0),"sint16, little endian, Typed Array"),nn(Int16Array,(n,e,t)=>ks(e,77,73,n,t)),Qe.registerDecoder(78,n=>On(n,Int32Array,!0),"sint32, little endian, Typed Array"),nn(Int32Array,(n,e,t)=>ks(e,78,74,n,t)),Qe.registerDecoder(79,n=>On(n,BigInt64Array,!0),"sint64, little endian, Typed Array"),nn(BigInt64Array,(n,e,t)=>ks(e,79,75,n,t)),Qe.registerDecoder(81,n=>On(n,Float32Array,!1),"IEEE 754 binary32, big endian, Typed Array"),Qe.registerDecoder(82,n=>On(n,Float64Array,!1),"IEEE 754 binary64, big endian, Typed Array"),Qe.registerDecoder(85,n=>On(n,Float32Array,!0),"IEEE 754 binary32, little endian, Typed Array"),nn(Float32Array,(n,e,t)=>ks(e,85,81,n,t)),Qe.registerDecoder(86,n=>On(n,Float64Array,!0),"IEEE 754 binary64, big endian, Typed Array"),nn(Float64Array,(n,e,t)=>ks(e,86,82,n,t)),Qe.registerDecoder(wt.SET,(n,e)=>{if(Lp(n.contents),e.sortKeys){let t=gn.decodeToEncodeOpts(e),i=null;for(let s of n.contents){let r=[s,void 0,Fs(s,t)];if(i&&e.sortKeys(i,r)>=0)throw new Error(`Set items out of order in tag #${wt.SET}`);i=r}}return new Set(n.contents)},"Set"),nn(Set,(n,e,t)=>{let i=[...n];if(t.sortKeys){let s=i.map(r=>[r,void 0,Fs(r,t)]);s.sort(t.sortKeys),i=s.map(([r])=>r)}return[wt.SET,i]}),Qe.registerDecoder(wt.JSON,n=>(us(n.contents),JSON.parse(n.contents)),"JSON-encoded");function Pp(n){return fs(n.contents),new fr().decode(n.contents)}Pp.comment=n=>{fs(n.contents);let e=new fr;return`(WTF8 string): ${JSON.stringify(e.decode(n.contents))}`},Qe.registerDecoder(wt.WTF8,Pp),Qe.registerDecoder(wt.SELF_DESCRIBED,n=>n.contents,"Self-Described"),Qe.registerDecoder(wt.INVALID_16,()=>{throw new Error(`Tag always invalid: ${wt.INVALID_16}`)},"Invalid"),Qe.registerDecoder(wt.INVALID_32,()=>{throw new Error(`Tag always invalid: ${wt.INVALID_32}`)},"Invalid"),Qe.registerDecoder(wt.INVALID_64,()=>{throw new Error(`Tag always invalid: ${wt.INVALID_64}`)},"Invalid"),Qe.registerDecoder(wt.SYMBOL,n=>{let e=n.contents;if(Array.isArray(n.contents)){if(n.contents.length!==1)throw new Error(`Expected Array of size 1: ${n.contents}`);[e]=n.contents}if(us(e),!e.length)throw new Error(`Expected non-empty string: ${n.contents}`);return Symbol.for(e)},"Symbol");function _u(n){throw new Error(`Encoding ${n.constructor.name} intentionally unimplmented.  It is not concrete enough to interoperate.  Convert to Uint8Array first.`)}nn(ArrayBuffer,_u),nn(DataView,_u),typeof SharedArrayBuffer<"u"&&nn(SharedArrayBuffer,_u);function xl(n){return[NaN,n.valueOf()]}nn(Boolean,xl),nn(Number,xl),nn(String,xl),nn(BigInt,xl);function rx(n){let e={...gn.defaultDecodeOptions};if(n.dcbor?Object.assign(e,gn.dcborDecodeOptions):n.cde&&Object.assign(e,gn.cdeDecodeOptions),Object.assign(e,n),Object.hasOwn(e,"rejectLongNumbers"))throw new TypeError("rejectLongNumbers has changed to requirePreferred");return e.boxed&&(e.saveOriginal=!0),e}var yu=class{parent=void 0;ret=void 0;step(e,t,i){if(this.ret=gn.create(e,this.parent,t,i),e[2]===Kt.BREAK)if(this.parent?.isStreaming)this.parent.left=0;else throw new Error("Unexpected BREAK");else this.parent&&this.parent.push(this.ret,i,e[3]);for(this.ret instanceof gn&&(this.parent=this.ret);this.parent?.done;){this.ret=this.parent.convert(i);let s=this.parent.parent;s?.replaceLast(this.ret,this.parent,i),this.parent=s}}};function vu(n,e={}){let t=rx(e),i=new $i(n,t),s=new yu;for(let r of i)s.step(r,t,i);return s.ret}var{cdeDecodeOptions:r1,dcborDecodeOptions:o1,defaultDecodeOptions:a1}=gn;function ox(n){let e=n instanceof Uint8Array?n:new Uint8Array(n);return vu(e)}var zs=class extends Error{},Sl=class{constructor(e){this.url=e;this.connect()}url;ws=null;subs=new Map;pending=new Map;goals=new Map;statusWaiters=new Map;nextId=1;closed=!1;retryMs=500;onState=()=>{};framesIn=0;bytesIn=0;connect(){this.onState("connecting");let e=new WebSocket(this.url);e.binaryType="arraybuffer",this.ws=e,e.onopen=()=>{this.retryMs=500,this.onState("open");for(let t of this.subs.values())this.sendSubscribe(t)},e.onmessage=t=>this.onFrame(t.data),e.onclose=t=>{this.onState("closed",t.reason||`code ${t.code}`);for(let[i,s]of this.pending)clearTimeout(s.timer),s.reject(new Error("connection to the hub lost")),this.pending.delete(i);this.closed||(setTimeout(()=>this.connect(),this.retryMs),this.retryMs=Math.min(this.retryMs*2,5e3))}}close(){this.closed=!0,this.ws?.close()}send(e){this.ws?.readyState===WebSocket.OPEN&&this.ws.send(JSON.stringify(e))}onFrame(e){let t=performance.now();this.framesIn++;let i,s=typeof e=="string"?e.length:e.byteLength;try{typeof e=="string"?(this.bytesIn+=e.length,i=JSON.parse(e)):(this.bytesIn+=e.byteLength,i=ox(e)),Ut.busyMs.decode+=performance.now()-t}catch(r){console.warn("undecodable frame from the hub",r);return}switch(i.op){case"publish":{let r=String(i.topic);for(let o of this.subs.values())if(o.topic===r||o.opts.regex&&new RegExp(`^(?:${o.topic})$`).test(r))for(let a of o.handlers)try{a(i.msg,r,t,s)}catch(l){console.error(`handler for ${r} failed`,l)}break}case"service_response":{let r=this.pending.get(String(i.id));if(!r)break;this.pending.delete(String(i.id)),clearTimeout(r.timer),i.result===!1?r.reject(new zs(typeof i.values=="string"?i.values:JSON.stringify(i.values))):r.resolve(i.values);break}case"action_feedback":{this.goals.get(String(i.id))?.onFeedback(i.values);break}case"action_result":{let r=this.goals.get(String(i.id));if(!r)break;this.goals.delete(String(i.id)),r.done.resolve({status:i.status,values:i.values,result:i.result});break}case"status":{let r=i.id===void 0?void 0:String(i.id);if(i.level==="error"&&r){let o=this.pending.get(r);o&&(this.pending.delete(r),clearTimeout(o.timer),o.reject(new zs(String(i.msg))));let a=this.goals.get(r);a&&(this.goals.delete(r),a.done.reject(new zs(String(i.msg)))),this.statusWaiters.get(r)?.(String(i.msg))}i.level==="error"&&!r&&console.warn("hub:",i.msg);break}}}sendSubscribe(e){this.send({op:"subscribe",id:`sub:${e.topic}`,topic:e.topic,type:e.opts.type,compression:e.opts.compression??"cbor",queue_length:e.opts.queue_length??1,throttle_rate:e.opts.throttle_rate??0,regex:e.opts.regex||void 0})}subscribe(e,t,i={}){let s=this.subs.get(e);return s||(s={topic:e,opts:i,handlers:new Set},this.subs.set(e,s),this.sendSubscribe(s)),s.handlers.add(t),()=>{let r=this.subs.get(e);r&&(r.handlers.delete(t),r.handlers.size===0&&(this.subs.delete(e),this.send({op:"unsubscribe",id:`sub:${e}`,topic:e})))}}call(e,t={},i=10){let s=`call:${this.nextId++}`;return new Promise((r,o)=>{let a=window.setTimeout(()=>{this.pending.delete(s),o(new Error(`${e}: no answer within ${i+2} s`))},(i+2)*1e3);this.pending.set(s,{resolve:r,reject:o,timer:a}),this.send({op:"call_service",id:s,service:e,args:t,timeout:i})})}advertise(e,t,i=1500){let s=`adv:${e}:${this.nextId++}`;return new Promise(r=>{let o=window.setTimeout(()=>{this.statusWaiters.delete(s),r(null)},i);this.statusWaiters.set(s,a=>{clearTimeout(o),this.statusWaiters.delete(s),r(a)}),this.send({op:"advertise",id:s,topic:e,type:t})})}unadvertise(e){this.send({op:"unadvertise",topic:e})}publish(e,t,i){let s=`pub:${e}:${this.nextId++}`;i&&(this.statusWaiters.set(s,r=>{this.statusWaiters.delete(s),i(r)}),setTimeout(()=>this.statusWaiters.delete(s),5e3)),this.send({op:"publish",id:s,topic:e,msg:t})}sendGoal(e,t,i,s){let r=`goal:${this.nextId++}`,o=new Promise((a,l)=>{this.goals.set(r,{onFeedback:s,done:{resolve:a,reject:l,timer:0}})});return this.send({op:"send_action_goal",id:r,action:e,action_type:t,args:i,feedback:!0}),{id:r,result:o,cancel:()=>this.send({op:"cancel_action_goal",id:r,action:e})}}};function ge(n,e="",t){let i=document.createElement(n);return e&&(i.className=e),t!==void 0&&(i.textContent=t),i}function un(n,e=1){return n==null||!Number.isFinite(n)?"–":Math.abs(n)>=100?n.toFixed(0):n.toFixed(e)}function $r(n){if(n==null||!Number.isFinite(n)||n<=0)return"–";let e=["B/s","kB/s","MB/s","GB/s"],t=n,i=0;for(;t>=1e3&&i<e.length-1;)t/=1e3,i++;return`${t.toFixed(t>=100?0:1)} ${e[i]}`}function Su(n){if(!n)return"never";let e=Math.max(0,(Date.now()-n)/1e3);return e<2?"just now":e<90?`${e.toFixed(0)} s ago`:e<5400?`${(e/60).toFixed(0)} min ago`:new Date(n).toLocaleString()}function Gs(n,e="",t){let i=ge("button",e,n);return t&&i.addEventListener("click",t),i}function ra(n,e="",t=0){if(n!==null&&typeof n=="object"){let s=ge("details");t<2&&(s.open=!0);let r=Object.entries(n);s.appendChild(ge("summary","",`${e}${e?": ":""}${Array.isArray(n)?`[${r.length}]`:`{${r.length}}`}`));for(let[o,a]of r)s.appendChild(ra(a,o,t+1));return s}let i=ge("div","leaf");return i.appendChild(ge("span","key",e?`${e}: `:"")),i.appendChild(ge("span",`val ${typeof n}`,JSON.stringify(n)??String(n))),i}function Np(n){n.innerHTML="";let e=ge("div","admin"),t=ge("section","panel wide");t.appendChild(ge("h2","","Audit log"));let i=ge("form","filters"),s={};for(let[y,A]of[["principal","user:alice"],["action","publish"],["name_regex","/robot1/.*"]]){let b=ge("input");b.name=y,b.placeholder=`${y} e.g. ${A}`,s[y]=b,i.appendChild(b)}let r=ge("select");r.name="allowed";for(let[y,A]of[["","allowed and denied"],["true","allowed only"],["false","denied only"]])r.appendChild(new Option(A,y));s.allowed=r,i.appendChild(r);let o=Gs("Filter","primary");o.type="submit",i.appendChild(o);let a=ge("table","audit"),l=ge("div","pager"),c=Gs("Next page →"),h=Gs("⇤ First page"),f=ge("span","muted");l.append(h,c,f),t.append(i,a,l);let u=ge("section","panel wide");u.appendChild(ge("h2","","Access rules"));let p=ge("div");u.appendChild(p),e.append(t,u),n.appendChild(e);let g=50,S=[null],d=0;async function m(){let y=new URLSearchParams({limit:String(g)});for(let[b,C]of Object.entries(s))C.value&&y.set(b,C.value);let A=S[d];A!=null&&y.set("cursor",typeof A=="string"?A:JSON.stringify(A));try{let b=await yi(`/api/v1/audit?${y}`);a.innerHTML="<thead><tr><th>time</th><th>principal</th><th>client</th><th>action</th><th>name</th><th>size</th><th>allowed</th><th>detail</th></tr></thead>";let C=ge("tbody");for(let E of b.records){let x=ge("tr",E.allowed?"":"denied"),T=E.at?.secs!=null?E.at.secs*1e3:typeof E.at=="number"?E.at>1e12?E.at:E.at*1e3:NaN;for(let k of[Number.isFinite(T)?new Date(T).toLocaleString():JSON.stringify(E.at),E.principal,E.client_ip,E.action,E.name,E.size??"",E.allowed?"yes":"no",E.detail??""])x.appendChild(ge("td","",String(k)));C.appendChild(x)}a.appendChild(C),S=S.slice(0,d+1),b.next!=null&&S.push(b.next),c.disabled=b.next==null,h.disabled=d===0,f.textContent=`page ${d+1} · ${b.records.length} records`}catch(b){a.replaceChildren(ge("caption","why",`The hub refused the audit log: ${b.message}`)),c.disabled=h.disabled=!0}}return i.addEventListener("submit",y=>{y.preventDefault(),S=[null],d=0,m()}),c.addEventListener("click",()=>{d++,m()}),h.addEventListener("click",()=>{d=0,m()}),m(),yi("/api/v1/rules").then(y=>{let A=ge("table","rules");A.innerHTML="<thead><tr><th>id</th><th>subject</th><th>names</th><th>ops</th><th>effect</th><th>comment</th></tr></thead>";let b=ge("tbody");for(let C of y.rules){let E=C.rule??C,x=ge("tr"),T=E.subject&&typeof E.subject=="object"?Object.entries(E.subject).map(([k,U])=>`${k}:${U}`).join(" "):E.subject;for(let k of[C.id??"",T,E.names,Array.isArray(E.ops)?E.ops.join(", "):E.ops,E.effect??"allow",E.comment??""])x.appendChild(ge("td","",typeof k=="string"||typeof k=="number"?String(k):JSON.stringify(k)));b.appendChild(x)}A.appendChild(b),p.replaceChildren(y.rules.length?A:ge("p","muted","No rules: only the built-in defaults apply (admin group, robots' own namespaces, anonymous read where enabled)."))},y=>p.replaceChildren(ge("p","why",`The hub refused the rules: ${y.message}`))),()=>{}}function bu(n){if(n instanceof Uint8Array)return n;if(ArrayBuffer.isView(n))return new Uint8Array(n.buffer,n.byteOffset,n.byteLength);if(typeof n=="string"){let e=atob(n),t=new Uint8Array(e.length);for(let i=0;i<e.length;i++)t[i]=e.charCodeAt(i);return t}return Array.isArray(n)?Uint8Array.from(n):new Uint8Array(0)}function wl(n){let e=n?.stamp;if(!e)return null;let t=e.sec??e.secs,i=e.nanosec??e.nsecs??0;return typeof t=="number"?t*1e3+i/1e6:null}function ax(n){return Math.atan2(2*(n.w*n.z+n.x*n.y),1-2*(n.y*n.y+n.z*n.z))}function El(n){let e=n?.pose;return e?.pose&&(e=e.pose),!e?.position||!e?.orientation?null:{x:e.position.x,y:e.position.y,yaw:ax(e.orientation)}}function Up(n){let e=n.ranges??[],t=new Float32Array(e.length*2),i=0;for(let s=0;s<e.length;s++){let r=e[s];if(!(r>=n.range_min&&r<=n.range_max))continue;let o=n.angle_min+s*n.angle_increment;t[i++]=r*Math.cos(o),t[i++]=r*Math.sin(o)}return t.subarray(0,i)}var bl={1:[1,(n,e)=>n.getInt8(e)],2:[1,(n,e)=>n.getUint8(e)],3:[2,(n,e,t)=>n.getInt16(e,t)],4:[2,(n,e,t)=>n.getUint16(e,t)],5:[4,(n,e,t)=>n.getInt32(e,t)],6:[4,(n,e,t)=>n.getUint32(e,t)],7:[4,(n,e,t)=>n.getFloat32(e,t)],8:[8,(n,e,t)=>n.getFloat64(e,t)]};function Op(n,e){let t=bu(n.data),i=(n.width??0)*(n.height??1),s=n.point_step,r=!n.is_bigendian,o=x=>n.fields.find(T=>T.name===x),a=o("x"),l=o("y"),c=o("z"),h=o("intensity");if(!a||!l||!c||!s)throw new Error("PointCloud2 without x, y, z fields");let f=e&&e.positions.length>=i*3?e.positions:new Float32Array(i*3),u=e&&e.intensity.length>=i?e.intensity:new Float32Array(i),p=new DataView(t.buffer,t.byteOffset,t.byteLength),g=r&&a.datatype===7&&l.datatype===7&&c.datatype===7,S=bl[a.datatype][1],d=bl[l.datatype][1],m=bl[c.datatype][1],y=h?bl[h.datatype]?.[1]:void 0,A=n.height??1,b=n.width??0,C=n.row_step||b*s,E=0;for(let x=0;x<A;x++)for(let T=0;T<b;T++){let k=x*C+T*s;if(k+s>t.byteLength)break;let U=g?p.getFloat32(k+a.offset,!0):S(p,k+a.offset,r),P=g?p.getFloat32(k+l.offset,!0):d(p,k+l.offset,r),B=g?p.getFloat32(k+c.offset,!0):m(p,k+c.offset,r);!Number.isFinite(U)||!Number.isFinite(P)||!Number.isFinite(B)||(f[E*3]=U,f[E*3+1]=P,f[E*3+2]=B,u[E]=y?y(p,k+h.offset,r):NaN,E++)}return{positions:f,intensity:u,count:E}}function Fp(n){return n.length>3&&n[0]===255&&n[1]===216&&n[2]===255?"jpeg":n.length>8&&n[0]===137&&n[1]===80&&n[2]===78&&n[3]===71?"png":"unknown"}function Ml(n,e=64){if(n instanceof Uint8Array)return`<${n.length} bytes>`;if(ArrayBuffer.isView(n)){let t=Array.from(n).slice(0,e),i=n.length;return i>e?[...t,`… ${i-e} more (${n.constructor.name})`]:t}if(Array.isArray(n)){let t=n.slice(0,e).map(i=>Ml(i,e));return n.length>e?[...t,`… ${n.length-e} more`]:t}if(n&&typeof n=="object"){let t={};for(let[i,s]of Object.entries(n))t[i]=Ml(s,e);return t}return n}var Dp={bool:!1,string:"",float32:0,float64:0,int8:0,uint8:0,int16:0,uint16:0,int32:0,uint32:0,int64:0,uint64:0,byte:0,char:0,time:{sec:0,nanosec:0},duration:{sec:0,nanosec:0}};function Bp(n,e){let t=e?n.find(s=>s.type===e):n[0],i=(s,r)=>{let o={};return!s||r>16||s.fieldnames.forEach((a,l)=>{let c=s.fieldtypes[l],h=s.fieldarraylen?.[l]??-1,f=c in Dp?Dp[c]:i(n.find(u=>u.type===c),r+1);o[a]=h===-1?f:h===0?[]:Array.from({length:h},()=>f)}),o};return i(t,0)}var kp=["#2f80ed","#eb5757","#27ae60","#f2994a","#9b51e0","#56ccf2","#bb6bd9","#219653"];function zp(n){return kp[n%kp.length]}var Zr=class{canvas=document.createElement("canvas");robots=new Map;scan=null;goal=null;selected=null;onClick=null;half=11;dirty=!0;raf=0;ro;constructor(e){this.canvas.className="map",e.appendChild(this.canvas),this.ro=new ResizeObserver(()=>this.invalidate()),this.ro.observe(this.canvas),this.canvas.addEventListener("click",i=>{if(!this.onClick)return;let[s,r]=this.toWorld(i.offsetX,i.offsetY);this.onClick(s,r,i)});let t=()=>{this.dirty&&this.draw(),this.raf=requestAnimationFrame(t)};this.raf=requestAnimationFrame(t)}destroy(){cancelAnimationFrame(this.raf),this.ro.disconnect(),this.canvas.remove()}invalidate(){this.dirty=!0}setPose(e,t,i){let s=this.robots.get(e);s||(s={name:e,pose:null,trail:[],online:!0,colour:i},this.robots.set(e,s));let r=performance.now();s.pose=t;let o=s.trail[s.trail.length-1];for((!o||Math.hypot(o.x-t.x,o.y-t.y)>.05||r-o.t>500)&&s.trail.push({x:t.x,y:t.y,t:r});s.trail.length&&r-s.trail[0].t>6e4;)s.trail.shift();let a=Math.max(Math.abs(t.x),Math.abs(t.y))+1;a>this.half&&(this.half=Math.ceil(a)),this.invalidate()}geometry(){let e=window.devicePixelRatio||1,t=this.canvas.clientWidth,i=this.canvas.clientHeight,s=Math.min(t,i)/(2*this.half);return{dpr:e,w:t,h:i,scale:s,cx:t/2,cy:i/2}}toWorld(e,t){let i=this.geometry();return[(e-i.cx)/i.scale,-(t-i.cy)/i.scale]}toScreen(e,t){let i=this.geometry();return[i.cx+e*i.scale,i.cy-t*i.scale]}draw(){this.dirty=!1;let e=this.geometry();if(e.w===0||e.h===0)return;(this.canvas.width!==Math.round(e.w*e.dpr)||this.canvas.height!==Math.round(e.h*e.dpr))&&(this.canvas.width=Math.round(e.w*e.dpr),this.canvas.height=Math.round(e.h*e.dpr));let t=this.canvas.getContext("2d");t.setTransform(e.dpr,0,0,e.dpr,0,0),t.fillStyle="#0f1720",t.fillRect(0,0,e.w,e.h);let i=(s,r)=>[e.cx+s*e.scale,e.cy-r*e.scale];for(let s=-this.half;s<=this.half;s++){t.strokeStyle=s===0?"#3b4a5a":s%5===0?"#24313e":"#18222c",t.lineWidth=1;let[r,o]=i(s,-this.half),[a,l]=i(s,this.half);t.beginPath(),t.moveTo(r,o),t.lineTo(a,l),t.stroke();let[c,h]=i(-this.half,s),[f,u]=i(this.half,s);t.beginPath(),t.moveTo(c,h),t.lineTo(f,u),t.stroke()}if(t.fillStyle="#5b6b7b",t.font="11px sans-serif",t.fillText(`1 m grid · ${2*this.half} m across`,8,e.h-8),this.scan){t.fillStyle="#f2c94c";for(let s=0;s<this.scan.length;s+=2){let[r,o]=i(this.scan[s],this.scan[s+1]);t.fillRect(r-1,o-1,2,2)}}if(this.goal){let[s,r]=i(this.goal.x,this.goal.y);t.strokeStyle="#6fcf97",t.lineWidth=2,t.beginPath(),t.arc(s,r,9,0,Math.PI*2),t.stroke(),t.beginPath(),t.moveTo(s-13,r),t.lineTo(s+13,r),t.moveTo(s,r-13),t.lineTo(s,r+13),t.stroke()}for(let s of this.robots.values()){let r=s.online?s.colour:"#56606a";if(s.trail.length>1&&(t.strokeStyle=r,t.globalAlpha=.55,t.lineWidth=2,t.beginPath(),s.trail.forEach((c,h)=>{let[f,u]=i(c.x,c.y);h===0?t.moveTo(f,u):t.lineTo(f,u)}),t.stroke(),t.globalAlpha=1),!s.pose)continue;let[o,a]=i(s.pose.x,s.pose.y),l=Math.max(9,e.scale*.45);t.save(),t.translate(o,a),t.rotate(-s.pose.yaw),t.fillStyle=r,t.strokeStyle=s.name===this.selected?"#ffffff":"#0b1016",t.lineWidth=2,t.beginPath(),t.moveTo(l,0),t.lineTo(-l*.7,l*.6),t.lineTo(-l*.4,0),t.lineTo(-l*.7,-l*.6),t.closePath(),t.fill(),t.stroke(),t.restore(),t.fillStyle=s.online?"#e0e6ec":"#7b8690",t.font="12px sans-serif",t.fillText(s.online?s.name:`${s.name} (offline)`,o+l+3,a-l*.5)}}};function Mu(n,e){let t=e.filter(r=>r.name.startsWith(`/${n}/`)),i=r=>t.find(o=>o.type===r),s=i("geometry_msgs/msg/PoseStamped")??i("nav_msgs/msg/Odometry")??i("geometry_msgs/msg/PoseWithCovarianceStamped");return s?{topic:s.name,type:s.type}:null}function lx(n,e){let t=0,i=0,s={};for(let r of e)if(r.name.startsWith(`/${n}/`)){t+=r.rate_hz,i+=r.bandwidth_bps;for(let[o,a]of Object.entries(r.drops??{}))a&&(s[o]=(s[o]??0)+a)}return{rate:t,bw:i,drops:s}}function Gp(n,e,t){n.innerHTML="";let i=ge("div","fleet"),s=ge("div","panel mapbox");s.appendChild(ge("h2","","Fleet map"));let r=ge("div","panel side");r.appendChild(ge("h2","","Robots"));let o=ge("div","robotlist");r.appendChild(o),i.append(s,r),n.appendChild(i);let a=new Zr(s);a.onClick=(g,S)=>{let d=null,m=1.2;for(let y of a.robots.values()){if(!y.pose)continue;let A=Math.hypot(y.pose.x-g,y.pose.y-S);A<m&&(d=y.name,m=A)}d&&t(d)};let l=new Map,c=new Map,h=!1;async function f(){let g=[],S=[];try{[{robots:g},{topics:S}]=await Promise.all([yi("/api/v1/robots"),yi("/api/v1/topics")])}catch(d){o.textContent=`cannot list robots: ${d.message}`;return}if(!h){g.sort((d,m)=>d.name.localeCompare(m.name,void 0,{numeric:!0})),g.forEach(d=>{c.has(d.name)||c.set(d.name,zp(c.size))});for(let d of g){let m=Mu(d.name,S),y=m?.topic;if(d.online&&m&&!l.has(y)){let b=c.get(d.name);l.set(y,e.subscribe(m.topic,C=>{let E=El(C);E&&(a.setPose(d.name,E,b),Ut.poses[d.name]={...E,at:Date.now()},si("fleet-pose"))},{type:m.type,throttle_rate:100,queue_length:1,compression:"none"}))}let A=a.robots.get(d.name);A&&A.online!==d.online&&(A.online=d.online,a.invalidate())}u(g,S)}}function u(g,S){o.innerHTML="",g.length===0&&o.appendChild(ge("p","muted","No robots visible to you yet."));for(let d of g){let m=lx(d.name,S),y=ge("div",`robot ${d.online?"online":"offline"}`);y.dataset.robot=d.name;let A=ge("div","robot-head"),b=ge("span","dot");b.style.background=d.online?c.get(d.name):"#56606a",A.append(b,ge("b","",d.name),ge("span",d.online?"badge ok":"badge off",d.online?"online":`offline · gone ${Su(d.last_seen_ms)}`)),y.appendChild(A);let C=ge("dl","kv"),E=(x,T,k="")=>{let U=ge("dt","",x),P=ge("dd","",T);k&&(P.title=k),C.append(U,P)};if(E("last seen",Su(d.last_seen_ms)),d.online){E("RTT",d.rtt_ms!=null?`${un(d.rtt_ms)} ms`:"–"),E("goodput",$r(d.link_rate_bps),"what the robot's link delivered (its link report)"),E("msg/s",un(m.rate),`${$r(m.bw)} over ${d.topics.length} topics`);let x=Object.entries(m.drops);E("drops",x.length?x.map(([T,k])=>`${T} ${k}`).join(", "):"none"),E("clock offset",d.clock_offset_ms!=null?`${un(d.clock_offset_ms)} ms`:"–"),E("share",d.share_bps?$r(d.share_bps):"unlimited","capacity share of the robot's site")}y.appendChild(C),y.addEventListener("click",()=>t(d.name)),o.appendChild(y)}}f();let p=window.setInterval(f,1e3);return()=>{h=!0,clearInterval(p);for(let g of l.values())g();a.destroy()}}var cx="uplot",hx="u-hz",ux="u-vt",fx="u-title",dx="u-wrap",px="u-under",mx="u-over",gx="u-axis",_r="u-off",_x="u-select",xx="u-cursor-x",yx="u-cursor-y",vx="u-cursor-pt",Sx="u-legend",bx="u-live",Mx="u-inline",wx="u-series",Ex="u-marker",Hp="u-label",Tx="u-value",aa="width",la="height";var Vp="bottom",Kr="left",wu="right",Gu="#000",Wp=Gu+"0",Eu="mousemove",Xp="mousedown",Tu="mouseup",qp="mouseenter",Yp="mouseleave",$p="dblclick",Ax="resize",Rx="scroll",Zp="change",Il="dppxchange",Hu="--",io=typeof window<"u",Pu=io?document:null,jr=io?window:null,Cx=io?navigator:null,Nt,Tl;function Lu(){let n=devicePixelRatio;Nt!=n&&(Nt=n,Tl&&Du(Zp,Tl,Lu),Tl=matchMedia(`(min-resolution: ${Nt-.001}dppx) and (max-resolution: ${Nt+.001}dppx)`),xr(Zp,Tl,Lu),jr.dispatchEvent(new CustomEvent(Il)))}function ri(n,e){if(e!=null){let t=n.classList;!t.contains(e)&&t.add(e)}}function Nu(n,e){let t=n.classList;t.contains(e)&&t.remove(e)}function Jt(n,e,t){n.style[e]=t+"px"}function Ri(n,e,t,i){let s=Pu.createElement(n);return e!=null&&ri(s,e),t?.insertBefore(s,i),s}function vi(n,e){return Ri("div",n,e)}var Kp=new WeakMap;function Zi(n,e,t,i,s){let r="translate("+e+"px,"+t+"px)",o=Kp.get(n);r!=o&&(n.style.transform=r,Kp.set(n,r),e<0||t<0||e>i||t>s?ri(n,_r):Nu(n,_r))}var Jp=new WeakMap;function jp(n,e,t){let i=e+t,s=Jp.get(n);i!=s&&(Jp.set(n,i),n.style.background=e,n.style.borderColor=t)}var Qp=new WeakMap;function em(n,e,t,i){let s=e+""+t,r=Qp.get(n);s!=r&&(Qp.set(n,s),n.style.height=t+"px",n.style.width=e+"px",n.style.marginLeft=i?-e/2+"px":0,n.style.marginTop=i?-t/2+"px":0)}var Vu={passive:!0},Ix={...Vu,capture:!0};function xr(n,e,t,i){e.addEventListener(n,t,i?Ix:Vu)}function Du(n,e,t,i){e.removeEventListener(n,t,Vu)}io&&Lu();function Ci(n,e,t,i){let s;t=t||0,i=i||e.length-1;let r=i<=2147483647;for(;i-t>1;)s=r?t+i>>1:oi((t+i)/2),e[s]<n?t=s:i=s;return n-e[t]<=e[i]-n?t:i}function Rm(n){return(t,i,s)=>{let r=-1,o=-1;for(let a=i;a<=s;a++)if(n(t[a])){r=a;break}for(let a=s;a>=i;a--)if(n(t[a])){o=a;break}return[r,o]}}var Cm=n=>n!=null,Im=n=>n!=null&&n>0,Nl=Rm(Cm),Px=Rm(Im);function Lx(n,e,t,i=0,s=!1){let r=s?Px:Nl,o=s?Im:Cm;[e,t]=r(n,e,t);let a=n[e],l=n[e];if(e>-1)if(i==1)a=n[e],l=n[t];else if(i==-1)a=n[t],l=n[e];else for(let c=e;c<=t;c++){let h=n[c];o(h)&&(h<a?a=h:h>l&&(l=h))}return[a??Wt,l??-Wt]}function Dl(n,e,t,i){let s=im(n),r=im(e);n==e&&(s==-1?(n*=t,e/=t):(n/=t,e*=t));let o=t==10?ds:Pm,a=s==1?oi:Si,l=r==1?Si:oi,c=a(o(Sn(n))),h=l(o(Sn(e))),f=Qr(t,c),u=Qr(t,h);return t==10&&(c<0&&(f=Xt(f,-c)),h<0&&(u=Xt(u,-h))),i||t==2?(n=f*s,e=u*r):(n=Um(n,f),e=Ul(e,u)),[n,e]}function Wu(n,e,t,i){let s=Dl(n,e,t,i);return n==0&&(s[0]=0),e==0&&(s[1]=0),s}var Xu=.1,tm={mode:3,pad:Xu},ha={pad:0,soft:null,mode:0},Nx={min:ha,max:ha};function Pl(n,e,t,i){return Ol(t)?nm(n,e,t):(ha.pad=t,ha.soft=i?0:null,ha.mode=i?3:0,nm(n,e,Nx))}function Pt(n,e){return n??e}function Dx(n,e,t){for(e=Pt(e,0),t=Pt(t,n.length-1);e<=t;){if(n[e]!=null)return!0;e++}return!1}function nm(n,e,t){let i=t.min,s=t.max,r=Pt(i.pad,0),o=Pt(s.pad,0),a=Pt(i.hard,-Wt),l=Pt(s.hard,Wt),c=Pt(i.soft,Wt),h=Pt(s.soft,-Wt),f=Pt(i.mode,0),u=Pt(s.mode,0),p=e-n,g=ds(p),S=Xn(Sn(n),Sn(e)),d=ds(S),m=Sn(d-g);(p<1e-24||m>10)&&(p=0,(n==0||e==0)&&(p=1e-24,f==2&&c!=Wt&&(r=0),u==2&&h!=-Wt&&(o=0)));let y=p||S||1e3,A=ds(y),b=Qr(10,oi(A)),C=y*(p==0?n==0?.1:1:r),E=Xt(Um(n-C,b/10),24),x=n>=c&&(f==1||f==3&&E<=c||f==2&&E>=c)?c:Wt,T=Xn(a,E<x&&n>=x?x:Ii(x,E)),k=y*(p==0?e==0?.1:1:o),U=Xt(Ul(e+k,b/10),24),P=e<=h&&(u==1||u==3&&U>=h||u==2&&U<=h)?h:-Wt,B=Ii(l,U>P&&e<=P?P:Xn(P,U));return T==B&&T==0&&(B=100),[T,B]}var Ux=new Intl.NumberFormat(io?Cx.language:"en-US"),qu=n=>Ux.format(n),ai=Math,Cl=ai.PI,Sn=ai.abs,oi=ai.floor,vn=ai.round,Si=ai.ceil,Ii=ai.min,Xn=ai.max,Qr=ai.pow,im=ai.sign,ds=ai.log10,Pm=ai.log2,Ox=(n,e=1)=>ai.sinh(n)*e,Au=(n,e=1)=>ai.asinh(n/e),Wt=1/0;function sm(n){return(ds((n^n>>31)-(n>>31))|0)+1}function Uu(n,e,t){return Ii(Xn(n,e),t)}function Lm(n){return typeof n=="function"}function Tt(n){return Lm(n)?n:()=>n}var Fx=()=>{},Nm=n=>n,Dm=(n,e)=>e,Bx=n=>null,rm=n=>!0,om=(n,e)=>n==e,kx=/\.\d*?(?=9{6,}|0{6,})/gm,yr=n=>{if(Fm(n)||Vs.has(n))return n;let e=`${n}`,t=e.match(kx);if(t==null)return n;let i=t[0].length-1;if(e.indexOf("e-")!=-1){let[s,r]=e.split("e");return+`${yr(s)}e${r}`}return Xt(n,i)};function mr(n,e){return yr(Xt(yr(n/e))*e)}function Ul(n,e){return yr(Si(yr(n/e))*e)}function Um(n,e){return yr(oi(yr(n/e))*e)}function Xt(n,e=0){if(Fm(n))return n;let t=10**e,i=n*t*(1+Number.EPSILON);return vn(i)/t}var Vs=new Map;function Om(n){return((""+n).split(".")[1]||"").length}function fa(n,e,t,i){let s=[],r=i.map(Om);for(let o=e;o<t;o++){let a=Sn(o),l=Xt(Qr(n,o),a);for(let c=0;c<i.length;c++){let h=n==10?+`${i[c]}e${o}`:i[c]*l,f=(o>=0?0:a)+(o>=r[c]?0:r[c]),u=n==10?h:Xt(h,f);s.push(u),Vs.set(u,f)}}return s}var ua={},Yu=[],eo=[null,null],Hs=Array.isArray,Fm=Number.isInteger,zx=n=>n===void 0;function am(n){return typeof n=="string"}function Ol(n){let e=!1;if(n!=null){let t=n.constructor;e=t==null||t==Object}return e}function Gx(n){return n!=null&&typeof n=="object"}var Hx=Object.getPrototypeOf(Uint8Array),Bm="__proto__";function to(n,e=Ol){let t;if(Hs(n)){let i=n.find(s=>s!=null);if(Hs(i)||e(i)){t=Array(n.length);for(let s=0;s<n.length;s++)t[s]=to(n[s],e)}else t=n.slice()}else if(n instanceof Hx)t=n.slice();else if(e(n)){t={};for(let i in n)i!=Bm&&(t[i]=to(n[i],e))}else t=n;return t}function _n(n){let e=arguments;for(let t=1;t<e.length;t++){let i=e[t];for(let s in i)s!=Bm&&(Ol(n[s])?_n(n[s],to(i[s])):n[s]=to(i[s]))}return n}var Vx=0,Wx=1,Xx=2;function qx(n,e,t){for(let i=0,s,r=-1;i<e.length;i++){let o=e[i];if(o>r){for(s=o-1;s>=0&&n[s]==null;)n[s--]=null;for(s=o+1;s<t&&n[s]==null;)n[r=s++]=null}}}function Yx(n,e){if(Kx(n)){let o=n[0].slice();for(let a=1;a<n.length;a++)o.push(...n[a].slice(1));return Jx(o[0])||(o=Zx(o)),o}let t=new Set;for(let o=0;o<n.length;o++){let l=n[o][0],c=l.length;for(let h=0;h<c;h++)t.add(l[h])}let i=[Array.from(t).sort((o,a)=>o-a)],s=i[0].length,r=new Map;for(let o=0;o<s;o++)r.set(i[0][o],o);for(let o=0;o<n.length;o++){let a=n[o],l=a[0];for(let c=1;c<a.length;c++){let h=a[c],f=Array(s).fill(void 0),u=e?e[o][c]:Wx,p=[];for(let g=0;g<h.length;g++){let S=h[g],d=r.get(l[g]);S===null?u!=Vx&&(f[d]=S,u==Xx&&p.push(d)):f[d]=S}qx(f,p,s),i.push(f)}}return i}var $x=typeof queueMicrotask>"u"?n=>Promise.resolve().then(n):queueMicrotask;function Zx(n){let e=n[0],t=e.length,i=Array(t);for(let r=0;r<i.length;r++)i[r]=r;i.sort((r,o)=>e[r]-e[o]);let s=[];for(let r=0;r<n.length;r++){let o=n[r],a=Array(t);for(let l=0;l<t;l++)a[l]=o[i[l]];s.push(a)}return s}function Kx(n){let e=n[0][0],t=e.length;for(let i=1;i<n.length;i++){let s=n[i][0];if(s.length!=t)return!1;if(s!=e){for(let r=0;r<t;r++)if(s[r]!=e[r])return!1}}return!0}function Jx(n,e=100){let t=n.length;if(t<=1)return!0;let i=0,s=t-1;for(;i<=s&&n[i]==null;)i++;for(;s>=i&&n[s]==null;)s--;if(s<=i)return!0;let r=Xn(1,oi((s-i+1)/e));for(let o=n[i],a=i+r;a<=s;a+=r){let l=n[a];if(l!=null){if(l<=o)return!1;o=l}}return!0}var km=["January","February","March","April","May","June","July","August","September","October","November","December"],zm=["Sunday","Monday","Tuesday","Wednesday","Thursday","Friday","Saturday"];function Gm(n){return n.slice(0,3)}var jx=zm.map(Gm),Qx=km.map(Gm),ey={MMMM:km,MMM:Qx,WWWW:zm,WWW:jx};function oa(n){return(n<10?"0":"")+n}function ty(n){return(n<10?"00":n<100?"0":"")+n}var ny={YYYY:n=>n.getFullYear(),YY:n=>(n.getFullYear()+"").slice(2),MMMM:(n,e)=>e.MMMM[n.getMonth()],MMM:(n,e)=>e.MMM[n.getMonth()],MM:n=>oa(n.getMonth()+1),M:n=>n.getMonth()+1,DD:n=>oa(n.getDate()),D:n=>n.getDate(),WWWW:(n,e)=>e.WWWW[n.getDay()],WWW:(n,e)=>e.WWW[n.getDay()],HH:n=>oa(n.getHours()),H:n=>n.getHours(),h:n=>{let e=n.getHours();return e==0?12:e>12?e-12:e},AA:n=>n.getHours()>=12?"PM":"AM",aa:n=>n.getHours()>=12?"pm":"am",a:n=>n.getHours()>=12?"p":"a",mm:n=>oa(n.getMinutes()),m:n=>n.getMinutes(),ss:n=>oa(n.getSeconds()),s:n=>n.getSeconds(),fff:n=>ty(n.getMilliseconds())};function $u(n,e){e=e||ey;let t=[],i=/\{([a-z]+)\}|[^{]+/gi,s;for(;s=i.exec(n);)t.push(s[0][0]=="{"?ny[s[1]]:s[0]);return r=>{let o="";for(let a=0;a<t.length;a++)o+=typeof t[a]=="string"?t[a]:t[a](r,e);return o}}var iy=new Intl.DateTimeFormat().resolvedOptions().timeZone;function sy(n,e){let t;return e=="UTC"||e=="Etc/UTC"?t=new Date(+n+n.getTimezoneOffset()*6e4):e==iy?t=n:(t=new Date(n.toLocaleString("en-US",{timeZone:e})),t.setMilliseconds(n.getMilliseconds())),t}var Hm=n=>n%1==0,Ll=[1,2,2.5,5],ry=fa(10,-32,0,Ll),Vm=fa(10,0,32,Ll),oy=Vm.filter(Hm),gr=ry.concat(Vm),Zu=`
`,Wm="{YYYY}",lm=Zu+Wm,Xm="{M}/{D}",ca=Zu+Xm,Al=ca+"/{YY}",qm="{aa}",ay="{h}:{mm}",Jr=ay+qm,cm=Zu+Jr,hm=":{ss}",Ot=null;function Ym(n){let e=n*1e3,t=e*60,i=t*60,s=i*24,r=s*30,o=s*365,l=(n==1?fa(10,0,3,Ll).filter(Hm):fa(10,-3,0,Ll)).concat([e,e*5,e*10,e*15,e*30,t,t*5,t*10,t*15,t*30,i,i*2,i*3,i*4,i*6,i*8,i*12,s,s*2,s*3,s*4,s*5,s*6,s*7,s*8,s*9,s*10,s*15,r,r*2,r*3,r*4,r*6,o,o*2,o*5,o*10,o*25,o*50,o*100]),c=[[o,Wm,Ot,Ot,Ot,Ot,Ot,Ot,1],[s*28,"{MMM}",lm,Ot,Ot,Ot,Ot,Ot,1],[s,Xm,lm,Ot,Ot,Ot,Ot,Ot,1],[i,"{h}"+qm,Al,Ot,ca,Ot,Ot,Ot,1],[t,Jr,Al,Ot,ca,Ot,Ot,Ot,1],[e,hm,Al+" "+Jr,Ot,ca+" "+Jr,Ot,cm,Ot,1],[n,hm+".{fff}",Al+" "+Jr,Ot,ca+" "+Jr,Ot,cm,Ot,1]];function h(f){return(u,p,g,S,d,m)=>{let y=[],A=d>=o,b=d>=r&&d<o,C=f(g),E=Xt(C*n,3),x=Ru(C.getFullYear(),A?0:C.getMonth(),b||A?1:C.getDate()),T=Xt(x*n,3);if(b||A){let k=b?d/r:0,U=A?d/o:0,P=E==T?E:Xt(Ru(x.getFullYear()+U,x.getMonth()+k,1)*n,3),B=new Date(vn(P/n)),z=B.getFullYear(),L=B.getMonth();for(let H=0;P<=S;H++){let W=Ru(z+U*H,L+k*H,1),D=W-f(Xt(W*n,3));P=Xt((+W+D)*n,3),P<=S&&y.push(P)}}else{let k=d>=s?s:d,U=oi(g)-oi(E),P=T+U+Ul(E-T,k);y.push(P);let B=f(P),z=B.getHours()+B.getMinutes()/t+B.getSeconds()/i,L=d/i,H=u.axes[p]._space,W=m/H;for(;P=Xt(P+d,n==1?0:3),!(P>S);)if(L>1){let D=oi(Xt(z+L,6))%24,q=f(P).getHours()-D;q>1&&(q=-1),P-=q*i,z=(z+L)%24;let j=y[y.length-1];Xt((P-j)/d,3)*W>=.7&&y.push(P)}else y.push(P)}return y}}return[l,c,h]}var[ly,cy,hy]=Ym(1),[uy,fy,dy]=Ym(.001);fa(2,-53,53,[1]);function um(n,e){return n.map(t=>t.map((i,s)=>s==0||s==8||i==null?i:e(s==1||t[8]==0?i:t[1]+i)))}function fm(n,e){return(t,i,s,r,o)=>{let a=e.find(g=>o>=g[0])||e[e.length-1],l,c,h,f,u,p;return i.map(g=>{let S=n(g),d=S.getFullYear(),m=S.getMonth(),y=S.getDate(),A=S.getHours(),b=S.getMinutes(),C=S.getSeconds(),E=d!=l&&a[2]||m!=c&&a[3]||y!=h&&a[4]||A!=f&&a[5]||b!=u&&a[6]||C!=p&&a[7]||a[1];return l=d,c=m,h=y,f=A,u=b,p=C,E(S)})}}function py(n,e){let t=$u(e);return(i,s,r,o,a)=>s.map(l=>t(n(l)))}function Ru(n,e,t){return new Date(n,e,t)}function dm(n,e){return e(n)}var my="{YYYY}-{MM}-{DD} {h}:{mm}{aa}";function pm(n,e){return(t,i,s,r)=>r==null?Hu:e(n(i))}function gy(n,e){let t=n.series[e];return t.width?t.stroke(n,e):t.points.width?t.points.stroke(n,e):null}function _y(n,e){return n.series[e].fill(n,e)}var xy={show:!0,live:!0,isolate:!1,mount:Fx,markers:{show:!0,width:2,stroke:gy,fill:_y,dash:"solid"},idx:null,idxs:null,values:[]};function yy(n,e){let t=n.cursor.points,i=vi(),s=t.size(n,e);Jt(i,aa,s),Jt(i,la,s);let r=s/-2;Jt(i,"marginLeft",r),Jt(i,"marginTop",r);let o=t.width(n,e,s);return o&&Jt(i,"borderWidth",o),i}function vy(n,e){let t=n.series[e].points;return t._fill||t._stroke}function Sy(n,e){let t=n.series[e].points;return t._stroke||t._fill}function by(n,e){return n.series[e].points.size}var Cu=[0,0];function My(n,e,t){return Cu[0]=e,Cu[1]=t,Cu}function Rl(n,e,t,i=!0){return s=>{s.button==0&&(!i||s.target==e)&&t(s)}}function Iu(n,e,t,i=!0){return s=>{(!i||s.target==e)&&t(s)}}var wy={show:!0,x:!0,y:!0,lock:!1,move:My,points:{one:!1,show:yy,size:by,width:0,stroke:Sy,fill:vy},bind:{mousedown:Rl,mouseup:Rl,click:Rl,dblclick:Rl,mousemove:Iu,mouseleave:Iu,mouseenter:Iu},drag:{setScale:!0,x:!0,y:!1,dist:0,uni:null,click:(n,e)=>{e.stopPropagation(),e.stopImmediatePropagation()},_x:!1,_y:!1},focus:{dist:(n,e,t,i,s)=>i-s,prox:-1,bias:0},hover:{skip:[void 0],prox:null,bias:0},left:-10,top:-10,idx:null,dataIdx:null,idxs:null,event:null},$m={show:!0,stroke:"rgba(0,0,0,0.07)",width:2},Ku=_n({},$m,{filter:Dm}),Zm=_n({},Ku,{size:10}),Km=_n({},$m,{show:!1}),Ju='12px system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, "Noto Sans", sans-serif, "Apple Color Emoji", "Segoe UI Emoji", "Segoe UI Symbol", "Noto Color Emoji"',Jm="bold "+Ju,jm=1.5,mm={show:!0,scale:"x",stroke:Gu,space:50,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Jm,side:2,grid:Ku,ticks:Zm,border:Km,font:Ju,lineGap:jm,rotate:0},Ey="Value",Ty="Time",gm={show:!0,scale:"x",auto:!1,sorted:1,min:Wt,max:-Wt,idxs:[]};function Ay(n,e,t,i,s){return e.map(r=>r==null?"":qu(r))}function Ry(n,e,t,i,s,r,o){let a=[],l=Vs.get(s)||0;t=o?t:Xt(Ul(t,s),l);for(let c=t;c<=i;c=Xt(c+s,l))a.push(Object.is(c,-0)?0:c);return a}function Ou(n,e,t,i,s,r,o){let a=[],l=n.scales[n.axes[e].scale].log,c=l==10?ds:Pm,h=oi(c(t));s=Qr(l,h),l==10&&(s=gr[Ci(s,gr)]);let f=t,u=s*l;l==10&&(u=gr[Ci(u,gr)]);do a.push(f),f=f+s,l==10&&!Vs.has(f)&&(f=Xt(f,Vs.get(s))),f>=u&&(s=f,u=s*l,l==10&&(u=gr[Ci(u,gr)]));while(f<=i);return a}function Cy(n,e,t,i,s,r,o){let l=n.scales[n.axes[e].scale].asinh,c=i>l?Ou(n,e,Xn(l,t),i,s):[l],h=i>=0&&t<=0?[0]:[];return(t<-l?Ou(n,e,Xn(l,-i),-t,s):[l]).reverse().map(u=>-u).concat(h,c)}var Qm=/./,Iy=/[12357]/,Py=/[125]/,_m=/1/,Fu=(n,e,t,i)=>n.map((s,r)=>e==4&&s==0||r%i==0&&t.test(s.toExponential()[s<0?1:0])?s:null);function Ly(n,e,t,i,s){let r=n.axes[t],o=r.scale,a=n.scales[o],l=n.valToPos,c=r._space,h=l(10,o),f=l(9,o)-h>=c?Qm:l(7,o)-h>=c?Iy:l(5,o)-h>=c?Py:_m;if(f==_m){let u=Sn(l(1,o)-h);if(u<c)return Fu(e.slice().reverse(),a.distr,f,Si(c/u)).reverse()}return Fu(e,a.distr,f,1)}function Ny(n,e,t,i,s){let r=n.axes[t],o=r.scale,a=r._space,l=n.valToPos,c=Sn(l(1,o)-l(2,o));return c<a?Fu(e.slice().reverse(),3,Qm,Si(a/c)).reverse():e}function Dy(n,e,t,i){return i==null?Hu:e==null?"":qu(e)}var xm={show:!0,scale:"y",stroke:Gu,space:30,gap:5,alignTo:1,size:50,labelGap:0,labelSize:30,labelFont:Jm,side:3,grid:Ku,ticks:Zm,border:Km,font:Ju,lineGap:jm,rotate:0};function Uy(n,e){let t=3+(n||1)*2;return Xt(t*e,3)}function Oy(n,e){let{scale:t,idxs:i}=n.series[0],s=n._data[0],r=n.valToPos(s[i[0]],t,!0),o=n.valToPos(s[i[1]],t,!0),a=Sn(o-r),l=n.series[e],c=a/(l.points.space*Nt);return i[1]-i[0]<=c}var ym={scale:null,auto:!0,sorted:0,min:Wt,max:-Wt},eg=(n,e,t,i,s)=>s,vm={show:!0,auto:!0,sorted:0,gaps:eg,alpha:1,facets:[_n({},ym,{scale:"x"}),_n({},ym,{scale:"y"})]},Sm={scale:"y",auto:!0,sorted:0,show:!0,spanGaps:!1,gaps:eg,alpha:1,points:{show:Oy,filter:null},values:null,min:Wt,max:-Wt,idxs:[],path:null,clip:null};function Fy(n,e,t,i,s){return t/10}var tg={time:!0,auto:!0,distr:1,log:10,asinh:1,min:null,max:null,dir:1,ori:0},By=_n({},tg,{time:!1,ori:1}),bm={};function ng(n,e){let t=bm[n];return t||(t={key:n,plots:[],sub(i){t.plots.push(i)},unsub(i){t.plots=t.plots.filter(s=>s!=i)},pub(i,s,r,o,a,l,c){for(let h=0;h<t.plots.length;h++)t.plots[h]!=s&&t.plots[h].pub(i,s,r,o,a,l,c)}},n!=null&&(bm[n]=t)),t}var no=1,Bu=2;function vr(n,e,t){let i=n.mode,s=n.series[e],r=i==2?n._data[e]:n._data,o=n.scales,a=n.bbox,l=r[0],c=i==2?r[1]:r[e],h=i==2?o[s.facets[0].scale]:o[n.series[0].scale],f=i==2?o[s.facets[1].scale]:o[s.scale],u=a.left,p=a.top,g=a.width,S=a.height,d=n.valToPosH,m=n.valToPosV;return h.ori==0?t(s,l,c,h,f,d,m,u,p,g,S,Bl,so,zl,sg,og):t(s,l,c,h,f,m,d,p,u,S,g,kl,ro,ef,rg,ag)}function ju(n,e){let t=0,i=0,s=Pt(n.bands,Yu);for(let r=0;r<s.length;r++){let o=s[r];o.series[0]==e?t=o.dir:o.series[1]==e&&(o.dir==1?i|=1:i|=2)}return[t,i==1?-1:i==2?1:i==3?2:0]}function ky(n,e,t,i,s){let r=n.mode,o=n.series[e],a=r==2?o.facets[1].scale:o.scale,l=n.scales[a];return s==-1?l.min:s==1?l.max:l.distr==3?l.dir==1?l.min:l.max:0}function ps(n,e,t,i,s,r){return vr(n,e,(o,a,l,c,h,f,u,p,g,S,d)=>{let m=o.pxRound,y=c.dir*(c.ori==0?1:-1),A=c.ori==0?so:ro,b,C;y==1?(b=t,C=i):(b=i,C=t);let E=m(f(a[b],c,S,p)),x=m(u(l[b],h,d,g)),T=m(f(a[C],c,S,p)),k=m(u(r==1?h.max:h.min,h,d,g)),U=new Path2D(s);return A(U,T,k),A(U,E,k),A(U,E,x),U})}function Fl(n,e,t,i,s,r){let o=null;if(n.length>0){o=new Path2D;let a=e==0?zl:ef,l=t;for(let f=0;f<n.length;f++){let u=n[f];if(u[1]>u[0]){let p=u[0]-l;p>0&&a(o,l,i,p,i+r),l=u[1]}}let c=t+s-l,h=10;c>0&&a(o,l,i-h/2,c,i+r+h)}return o}function zy(n,e,t){let i=n[n.length-1];i&&i[0]==e?i[1]=t:n.push([e,t])}function Qu(n,e,t,i,s,r,o){let a=[],l=n.length;for(let c=s==1?t:i;c>=t&&c<=i;c+=s)if(e[c]===null){let f=c,u=c;if(s==1)for(;++c<=i&&e[c]===null;)u=c;else for(;--c>=t&&e[c]===null;)u=c;let p=r(n[f]),g=u==f?p:r(n[u]),S=f-s;p=o<=0&&S>=0&&S<l?r(n[S]):p;let m=u+s;g=o>=0&&m>=0&&m<l?r(n[m]):g,g>=p&&a.push([p,g])}return a}function Mm(n){return n==0?Nm:n==1?vn:e=>mr(e,n)}function ig(n){let e=n==0?Bl:kl,t=n==0?(s,r,o,a,l,c)=>{s.arcTo(r,o,a,l,c)}:(s,r,o,a,l,c)=>{s.arcTo(o,r,l,a,c)},i=n==0?(s,r,o,a,l)=>{s.rect(r,o,a,l)}:(s,r,o,a,l)=>{s.rect(o,r,l,a)};return(s,r,o,a,l,c=0,h=0)=>{c==0&&h==0?i(s,r,o,a,l):(c=Ii(c,a/2,l/2),h=Ii(h,a/2,l/2),e(s,r+c,o),t(s,r+a,o,r+a,o+l,c),t(s,r+a,o+l,r,o+l,h),t(s,r,o+l,r,o,h),t(s,r,o,r+a,o,c),s.closePath())}}var Bl=(n,e,t)=>{n.moveTo(e,t)},kl=(n,e,t)=>{n.moveTo(t,e)},so=(n,e,t)=>{n.lineTo(e,t)},ro=(n,e,t)=>{n.lineTo(t,e)},zl=ig(0),ef=ig(1),sg=(n,e,t,i,s,r)=>{n.arc(e,t,i,s,r)},rg=(n,e,t,i,s,r)=>{n.arc(t,e,i,s,r)},og=(n,e,t,i,s,r,o)=>{n.bezierCurveTo(e,t,i,s,r,o)},ag=(n,e,t,i,s,r,o)=>{n.bezierCurveTo(t,e,s,i,o,r)};function lg(n){return(e,t,i,s,r)=>vr(e,t,(o,a,l,c,h,f,u,p,g,S,d)=>{let{pxRound:m,points:y}=o,A,b;c.ori==0?(A=Bl,b=sg):(A=kl,b=rg);let C=Xt(y.width*Nt,3),E=(y.size-y.width)/2*Nt,x=Xt(E*2,3),T=new Path2D,k=new Path2D,{left:U,top:P,width:B,height:z}=e.bbox;zl(k,U-x,P-x,B+x*2,z+x*2);let L=H=>{if(l[H]!=null){let W=m(f(a[H],c,S,p)),D=m(u(l[H],h,d,g));A(T,W+E,D),b(T,W,D,E,0,Cl*2)}};if(r)r.forEach(L);else for(let H=i;H<=s;H++)L(H);return{stroke:C>0?T:null,fill:T,clip:k,flags:no|Bu}})}function cg(n){return(e,t,i,s,r,o)=>{i!=s&&(r!=i&&o!=i&&n(e,t,i),r!=s&&o!=s&&n(e,t,s),n(e,t,o))}}var Gy=cg(so),Hy=cg(ro);function hg(n){let e=Pt(n?.alignGaps,0);return(t,i,s,r)=>vr(t,i,(o,a,l,c,h,f,u,p,g,S,d)=>{[s,r]=Nl(l,s,r);let m=o.pxRound,y=z=>m(f(z,c,S,p)),A=z=>m(u(z,h,d,g)),b,C;c.ori==0?(b=so,C=Gy):(b=ro,C=Hy);let E=c.dir*(c.ori==0?1:-1),x={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:no},T=x.stroke,k=!1;if(r-s>=S*4){let z=ce=>t.posToVal(ce,c.key,!0),L=null,H=null,W,D,te,X=y(a[E==1?s:r]),q=y(a[s]),j=y(a[r]),ae=z(E==1?q+1:j-1);for(let ce=E==1?s:r;ce>=s&&ce<=r;ce+=E){let ee=a[ce],fe=(E==1?ee<ae:ee>ae)?X:y(ee),Me=l[ce];fe==X?Me!=null?(D=Me,L==null?(b(T,fe,A(D)),W=L=H=D):D<L?L=D:D>H&&(H=D)):Me===null&&(k=!0):(L!=null&&C(T,X,A(L),A(H),A(W),A(D)),Me!=null?(D=Me,b(T,fe,A(D)),L=H=W=D):(L=H=null,Me===null&&(k=!0)),X=fe,ae=z(X+E))}L!=null&&L!=H&&te!=X&&C(T,X,A(L),A(H),A(W),A(D))}else for(let z=E==1?s:r;z>=s&&z<=r;z+=E){let L=l[z];L===null?k=!0:L!=null&&b(T,y(a[z]),A(L))}let[P,B]=ju(t,i);if(o.fill!=null||P!=0){let z=x.fill=new Path2D(T),L=o.fillTo(t,i,o.min,o.max,P),H=A(L),W=y(a[s]),D=y(a[r]);E==-1&&([D,W]=[W,D]),b(z,D,H),b(z,W,H)}if(!o.spanGaps){let z=[];k&&z.push(...Qu(a,l,s,r,E,y,e)),x.gaps=z=o.gaps(t,i,s,r,z),x.clip=Fl(z,c.ori,p,g,S,d)}return B!=0&&(x.band=B==2?[ps(t,i,s,r,T,-1),ps(t,i,s,r,T,1)]:ps(t,i,s,r,T,B)),x})}function Vy(n){let e=Pt(n.align,1),t=Pt(n.ascDesc,!1),i=Pt(n.alignGaps,0),s=Pt(n.extend,!1);return(r,o,a,l)=>vr(r,o,(c,h,f,u,p,g,S,d,m,y,A)=>{[a,l]=Nl(f,a,l);let b=c.pxRound,{left:C,width:E}=r.bbox,x=q=>b(g(q,u,y,d)),T=q=>b(S(q,p,A,m)),k=u.ori==0?so:ro,U={stroke:new Path2D,fill:null,clip:null,band:null,gaps:null,flags:no},P=U.stroke,B=u.dir*(u.ori==0?1:-1),z=T(f[B==1?a:l]),L=x(h[B==1?a:l]),H=L,W=L;s&&e==-1&&(W=C,k(P,W,z)),k(P,L,z);for(let q=B==1?a:l;q>=a&&q<=l;q+=B){let j=f[q];if(j==null)continue;let ae=x(h[q]),ce=T(j);e==1?k(P,ae,z):k(P,H,ce),k(P,ae,ce),z=ce,H=ae}let D=H;s&&e==1&&(D=C+E,k(P,D,z));let[te,X]=ju(r,o);if(c.fill!=null||te!=0){let q=U.fill=new Path2D(P),j=c.fillTo(r,o,c.min,c.max,te),ae=T(j);k(q,D,ae),k(q,W,ae)}if(!c.spanGaps){let q=[];q.push(...Qu(h,f,a,l,B,x,i));let j=c.width*Nt/2,ae=t||e==1?j:-j,ce=t||e==-1?-j:j;q.forEach(ee=>{ee[0]+=ae,ee[1]+=ce}),U.gaps=q=c.gaps(r,o,a,l,q),U.clip=Fl(q,u.ori,d,m,y,A)}return X!=0&&(U.band=X==2?[ps(r,o,a,l,P,-1),ps(r,o,a,l,P,1)]:ps(r,o,a,l,P,X)),U})}function wm(n,e,t,i,s,r,o=Wt){if(n.length>1){let a=null;for(let l=0,c=1/0;l<n.length;l++)if(e[l]!==void 0){if(a!=null){let h=Sn(n[l]-n[a]);h<c&&(c=h,o=Sn(t(n[l],i,s,r)-t(n[a],i,s,r)))}a=l}}return o}function Wy(n){n=n||ua;let e=Pt(n.size,[.6,Wt,1]),t=n.align||0,i=n.gap||0,s=n.radius;s=s==null?[0,0]:typeof s=="number"?[s,0]:s;let r=Tt(s),o=1-e[0],a=Pt(e[1],Wt),l=Pt(e[2],1),c=Pt(n.disp,ua),h=Pt(n.each,p=>{}),{fill:f,stroke:u}=c;return(p,g,S,d)=>vr(p,g,(m,y,A,b,C,E,x,T,k,U,P)=>{let B=m.pxRound,z=t,L=i*Nt,H=a*Nt,W=l*Nt,D,te;b.ori==0?[D,te]=r(p,g):[te,D]=r(p,g);let X=b.dir*(b.ori==0?1:-1),q=b.ori==0?zl:ef,j=b.ori==0?h:(Pe,je,ht,Ee,Vt,Xe,Ke)=>{h(Pe,je,ht,Vt,Ee,Ke,Xe)},ae=Pt(p.bands,Yu).find(Pe=>Pe.series[0]==g),ce=ae!=null?ae.dir:0,ee=m.fillTo(p,g,m.min,m.max,ce),pe=B(x(ee,C,P,k)),fe,Me,ye,qe=U,it=B(m.width*Nt),We=!1,Ce=null,Ne=null,Be=null,xt=null;f!=null&&(it==0||u!=null)&&(We=!0,Ce=f.values(p,g,S,d),Ne=new Map,new Set(Ce).forEach(Pe=>{Pe!=null&&Ne.set(Pe,new Path2D)}),it>0&&(Be=u.values(p,g,S,d),xt=new Map,new Set(Be).forEach(Pe=>{Pe!=null&&xt.set(Pe,new Path2D)})));let{x0:Rt,size:Bt}=c;if(Rt!=null&&Bt!=null){z=1,y=Rt.values(p,g,S,d),Rt.unit==2&&(y=y.map(ht=>p.posToVal(T+ht*U,b.key,!0)));let Pe=Bt.values(p,g,S,d);Bt.unit==2?Me=Pe[0]*U:Me=E(Pe[0],b,U,T)-E(0,b,U,T),qe=wm(y,A,E,b,U,T,qe),ye=qe-Me+L}else qe=wm(y,A,E,b,U,T,qe),ye=qe*o+L,Me=qe-ye;ye<1&&(ye=0),it>=Me/2&&(it=0),ye<5&&(B=Nm);let at=ye>0,Ct=qe-ye-(at?it:0);Me=B(Uu(Ct,W,H)),fe=(z==0?Me/2:z==X?0:Me)-z*X*((z==0?L/2:0)+(at?it/2:0));let Ze={stroke:null,fill:null,clip:null,band:null,gaps:null,flags:0},ft=We?null:new Path2D,pt=null;if(ae!=null)pt=p.data[ae.series[1]];else{let{y0:Pe,y1:je}=c;Pe!=null&&je!=null&&(A=je.values(p,g,S,d),pt=Pe.values(p,g,S,d))}let bt=D*Me,O=te*Me;for(let Pe=X==1?S:d;Pe>=S&&Pe<=d;Pe+=X){let je=A[Pe];if(je==null)continue;if(pt!=null){let Y=pt[Pe]??0;if(je-Y==0)continue;pe=x(Y,C,P,k)}let ht=b.distr!=2||c!=null?y[Pe]:Pe,Ee=E(ht,b,U,T),Vt=x(Pt(je,ee),C,P,k),Xe=B(Ee-fe),Ke=B(Xn(Vt,pe)),R=B(Ii(Vt,pe)),v=Ke-R;if(je!=null){let Y=je<0?O:bt,ue=je<0?bt:O;We?(it>0&&Be[Pe]!=null&&q(xt.get(Be[Pe]),Xe,R+oi(it/2),Me,Xn(0,v-it),Y,ue),Ce[Pe]!=null&&q(Ne.get(Ce[Pe]),Xe,R+oi(it/2),Me,Xn(0,v-it),Y,ue)):q(ft,Xe,R+oi(it/2),Me,Xn(0,v-it),Y,ue),j(p,g,Pe,Xe-it/2,R,Me+it,v)}}return it>0?Ze.stroke=We?xt:ft:We||(Ze._fill=m.width==0?m._fill:m._stroke??m._fill,Ze.width=0),Ze.fill=We?Ne:ft,Ze})}function Xy(n,e){let t=Pt(e?.alignGaps,0);return(i,s,r,o)=>vr(i,s,(a,l,c,h,f,u,p,g,S,d,m)=>{[r,o]=Nl(c,r,o);let y=a.pxRound,A=D=>y(u(D,h,d,g)),b=D=>y(p(D,f,m,S)),C,E,x;h.ori==0?(C=Bl,x=so,E=og):(C=kl,x=ro,E=ag);let T=h.dir*(h.ori==0?1:-1),k=A(l[T==1?r:o]),U=k,P=[],B=[];for(let D=T==1?r:o;D>=r&&D<=o;D+=T)if(c[D]!=null){let X=l[D],q=A(X);P.push(U=q),B.push(b(c[D]))}let z={stroke:n(P,B,C,x,E,y),fill:null,clip:null,band:null,gaps:null,flags:no},L=z.stroke,[H,W]=ju(i,s);if(a.fill!=null||H!=0){let D=z.fill=new Path2D(L),te=a.fillTo(i,s,a.min,a.max,H),X=b(te);x(D,U,X),x(D,k,X)}if(!a.spanGaps){let D=[];D.push(...Qu(l,c,r,o,T,A,t)),z.gaps=D=a.gaps(i,s,r,o,D),z.clip=Fl(D,h.ori,g,S,d,m)}return W!=0&&(z.band=W==2?[ps(i,s,r,o,L,-1),ps(i,s,r,o,L,1)]:ps(i,s,r,o,L,W)),z})}function qy(n){return Xy(Yy,n)}function Yy(n,e,t,i,s,r){let o=n.length;if(o<2)return null;let a=new Path2D;if(t(a,n[0],e[0]),o==2)i(a,n[1],e[1]);else{let l=Array(o),c=Array(o-1),h=Array(o-1),f=Array(o-1);for(let u=0;u<o-1;u++)h[u]=e[u+1]-e[u],f[u]=n[u+1]-n[u],c[u]=h[u]/f[u];l[0]=c[0];for(let u=1;u<o-1;u++)c[u]===0||c[u-1]===0||c[u-1]>0!=c[u]>0?l[u]=0:(l[u]=3*(f[u-1]+f[u])/((2*f[u]+f[u-1])/c[u-1]+(f[u]+2*f[u-1])/c[u]),isFinite(l[u])||(l[u]=0));l[o-1]=c[o-2];for(let u=0;u<o-1;u++)s(a,n[u]+f[u]/3,e[u]+l[u]*f[u]/3,n[u+1]-f[u]/3,e[u+1]-l[u+1]*f[u]/3,n[u+1],e[u+1])}return a}var ku=new Set;function Em(){for(let n of ku)n.syncRect(!0)}io&&(xr(Ax,jr,Em),xr(Rx,jr,Em,!0),xr(Il,jr,()=>{Cn.pxRatio=Nt}));var $y=hg(),Zy=lg();function Tm(n,e,t,i){return(i?[n[0],n[1]].concat(n.slice(2)):[n[0]].concat(n.slice(1))).map((r,o)=>zu(r,o,e,t))}function Ky(n,e){return n.map((t,i)=>i==0?{}:_n({},e,t))}function zu(n,e,t,i){return _n({},e==0?t:i,n)}function ug(n,e,t){return e==null?eo:[e,t]}var Jy=ug;function jy(n,e,t){return e==null?eo:Pl(e,t,Xu,!0)}function fg(n,e,t,i){return e==null?eo:Dl(e,t,n.scales[i].log,!1)}var Qy=fg;function dg(n,e,t,i){return e==null?eo:Wu(e,t,n.scales[i].log,!1)}var ev=dg;function tv(n,e,t,i,s){let r=Xn(sm(n),sm(e)),o=e-n,a=Ci(s/i*o,t);do{let l=t[a],c=i*l/o;if(c>=s&&r+(l<5?Vs.get(l):0)<=17)return[l,c]}while(++a<t.length);return[0,0]}function Am(n){let e,t;return n=n.replace(/(\d+)px/,(i,s)=>(e=vn((t=+s)*Nt))+"px"),[n,e,t]}function nv(n){n.show&&[n.font,n.labelFont].forEach(e=>{let t=Xt(e[2]*Nt,1);e[0]=e[0].replace(/[0-9.]+px/,t+"px"),e[1]=t})}function Cn(n,e,t){let i={mode:Pt(n.mode,1)},s=i.mode;function r(_,M,I,N){let V=M.valToPct(_);return N+I*(M.dir==-1?1-V:V)}function o(_,M,I,N){let V=M.valToPct(_);return N+I*(M.dir==-1?V:1-V)}function a(_,M,I,N){return M.ori==0?r(_,M,I,N):o(_,M,I,N)}i.valToPosH=r,i.valToPosV=o;let l=!1;i.status=0;let c=i.root=vi(cx);if(n.id!=null&&(c.id=n.id),ri(c,n.class),n.title){let _=vi(fx,c);_.textContent=n.title}let h=Ri("canvas"),f=i.ctx=h.getContext("2d"),u=vi(dx,c);xr("click",u,_=>{_.target===g&&(Yt!=zr||Qt!=Gr)&&Nn.click(i,_)},!0);let p=i.under=vi(px,u);u.appendChild(h);let g=i.over=vi(mx,u);n=to(n);let S=+Pt(n.pxAlign,1),d=Mm(S);(n.plugins||[]).forEach(_=>{_.opts&&(n=_.opts(i,n)||n)});let m=n.ms||.001,y=i.series=s==1?Tm(n.series||[],gm,Sm,!1):Ky(n.series||[null],vm),A=i.axes=Tm(n.axes||[],mm,xm,!0),b=i.scales={},C=i.bands=n.bands||[];C.forEach(_=>{_.fill=Tt(_.fill||null),_.dir=Pt(_.dir,-1)});let E=s==2?y[1].facets[0].scale:y[0].scale,x={axes:as,series:vt},T=(n.drawOrder||["axes","series"]).map(_=>x[_]);function k(_){let M=_.distr==3?I=>ds(I>0?I:_.clamp(i,I,_.min,_.max,_.key)):_.distr==4?I=>Au(I,_.asinh):_.distr==100?I=>_.fwd(I):I=>I;return I=>{let N=M(I),{_min:V,_max:J}=_,le=J-V;return(N-V)/le}}function U(_){let M=b[_];if(M==null){let I=(n.scales||ua)[_]||ua;if(I.from!=null){U(I.from);let N=_n({},b[I.from],I,{key:_});N.valToPct=k(N),b[_]=N}else{M=b[_]=_n({},_==E?tg:By,I),M.key=_;let N=M.time,V=M.range,J=Hs(V);if((_!=E||s==2&&!N)&&(J&&(V[0]==null||V[1]==null)&&(V={min:V[0]==null?tm:{mode:1,hard:V[0],soft:V[0]},max:V[1]==null?tm:{mode:1,hard:V[1],soft:V[1]}},J=!1),!J&&Ol(V))){let le=V;V=(de,be,Oe)=>be==null?eo:Pl(be,Oe,le)}M.range=Tt(V||(N?Jy:_==E?M.distr==3?Qy:M.distr==4?ev:ug:M.distr==3?fg:M.distr==4?dg:jy)),M.auto=Tt(J?!1:M.auto),M.clamp=Tt(M.clamp||Fy),M._min=M._max=null,M.valToPct=k(M)}}}U("x"),U("y"),s==1&&y.forEach(_=>{U(_.scale)}),A.forEach(_=>{U(_.scale)});for(let _ in n.scales)U(_);let P=b[E],B=P.distr,z,L;P.ori==0?(ri(c,hx),z=r,L=o):(ri(c,ux),z=o,L=r);let H={};for(let _ in b){let M=b[_];(M.min!=null||M.max!=null)&&(H[_]={min:M.min,max:M.max},M.min=M.max=null)}let W=n.tzDate||(_=>new Date(vn(_/m))),D=n.fmtDate||$u,te=m==1?hy(W):dy(W),X=fm(W,um(m==1?cy:fy,D)),q=pm(W,dm(my,D)),j=[],ae=i.legend=_n({},xy,n.legend),ce=i.cursor=_n({},wy,{drag:{y:s==2}},n.cursor),ee=ae.show,pe=ce.show,fe=ae.markers;ae.idxs=j,fe.width=Tt(fe.width),fe.dash=Tt(fe.dash),fe.stroke=Tt(fe.stroke),fe.fill=Tt(fe.fill);let Me,ye,qe,it=[],We=[],Ce,Ne=!1,Be={};if(ae.live){let _=y[1]?y[1].values:null;Ne=_!=null,Ce=Ne?_(i,1,0):{_:0};for(let M in Ce)Be[M]=Hu}if(ee)if(Me=Ri("table",Sx,c),qe=Ri("tbody",null,Me),ae.mount(i,Me),Ne){ye=Ri("thead",null,Me,qe);let _=Ri("tr",null,ye);Ri("th",null,_);for(var xt in Ce)Ri("th",Hp,_).textContent=xt}else ri(Me,Mx),ae.live&&ri(Me,bx);let Rt={show:!0},Bt={show:!1};function at(_,M){if(M==0&&(Ne||!ae.live||s==2))return eo;let I=[],N=Ri("tr",wx,qe,qe.childNodes[M]);ri(N,_.class),_.show||ri(N,_r);let V=Ri("th",null,N);if(fe.show){let de=vi(Ex,V);if(M>0){let be=fe.width(i,M);be&&(de.style.border=be+"px "+fe.dash(i,M)+" "+fe.stroke(i,M)),de.style.background=fe.fill(i,M)}}let J=vi(Hp,V);_.label instanceof HTMLElement?J.appendChild(_.label):J.textContent=_.label,M>0&&(fe.show||(J.style.color=_.width>0?fe.stroke(i,M):fe.fill(i,M)),Ze("click",V,de=>{if(ce._lock)return;tt(de);let be=y.indexOf(_);if((de.ctrlKey||de.metaKey)!=ae.isolate){let Oe=y.some((Fe,ze)=>ze>0&&ze!=be&&Fe.show);y.forEach((Fe,ze)=>{ze>0&&Vi(ze,Oe?ze==be?Rt:Bt:Rt,!0,mn.setSeries)})}else Vi(be,{show:!_.show},!0,mn.setSeries)},!1),nt&&Ze(qp,V,de=>{ce._lock||(tt(de),Vi(y.indexOf(_),Vr,!0,mn.setSeries))},!1));for(var le in Ce){let de=Ri("td",Tx,N);de.textContent="--",I.push(de)}return[N,I]}let Ct=new Map;function Ze(_,M,I,N=!0){let V=Ct.get(M)||{},J=ce.bind[_](i,M,I,N);J&&(xr(_,M,V[_]=J),Ct.set(M,V))}function ft(_,M,I){let N=Ct.get(M)||{};for(let V in N)(_==null||V==_)&&(Du(V,M,N[V]),delete N[V]);_==null&&Ct.delete(M)}let pt=0,bt=0,O=0,Pe=0,je=0,ht=0,Ee=je,Vt=ht,Xe=O,Ke=Pe,R=0,v=0,Y=0,ue=0;i.bbox={};let oe=!1,ve=!1,Se=!1,ne=!1,se=!1,me=!1;function F(_,M,I){(I||_!=i.width||M!=i.height)&&re(_,M),mt(!1),Se=!0,ve=!0,Un()}function re(_,M){i.width=pt=O=_,i.height=bt=Pe=M,je=ht=0,we(),Ye();let I=i.bbox;R=I.left=mr(je*Nt,.5),v=I.top=mr(ht*Nt,.5),Y=I.width=mr(O*Nt,.5),ue=I.height=mr(Pe*Nt,.5)}let ie=3;function Te(){let _=!1,M=0;for(;!_;){M++;let I=Fr(M),N=Hi(M);_=M==ie||I&&N,_||(re(i.width,i.height),ve=!0)}}function xe({width:_,height:M}){F(_,M)}i.setSize=xe;function we(){let _=!1,M=!1,I=!1,N=!1;A.forEach((V,J)=>{if(V.show&&V._show){let{side:le,_size:de}=V,be=le%2,Oe=V.label!=null?V.labelSize:0,Fe=de+Oe;Fe>0&&(be?(O-=Fe,le==3?(je+=Fe,N=!0):I=!0):(Pe-=Fe,le==0?(ht+=Fe,_=!0):M=!0))}}),zi[0]=_,zi[1]=I,zi[2]=M,zi[3]=N,O-=wi[1]+wi[3],je+=wi[3],Pe-=wi[2]+wi[0],ht+=wi[0]}function Ye(){let _=je+O,M=ht+Pe,I=je,N=ht;function V(J,le){switch(J){case 1:return _+=le,_-le;case 2:return M+=le,M-le;case 3:return I-=le,I+le;case 0:return N-=le,N+le}}A.forEach((J,le)=>{if(J.show&&J._show){let de=J.side;J._pos=V(de,J._size),J.label!=null&&(J._lpos=V(de,J.labelSize))}})}if(ce.dataIdx==null){let _=ce.hover,M=_.skip=new Set(_.skip??[]);M.add(void 0);let I=_.prox=Tt(_.prox),N=_.bias??=0;ce.dataIdx=(V,J,le,de)=>{if(J==0)return le;let be=le,Oe=I(V,J,le,de)??Wt,Fe=Oe>=0&&Oe<Wt,ze=P.ori==0?O:Pe,lt=ce.left,Lt=e[0],It=e[J];if(M.has(It[le])){be=null;let Mt=null,et=null,$e;if(N==0||N==-1)for($e=le;Mt==null&&$e-- >0;)M.has(It[$e])||(Mt=$e);if(N==0||N==1)for($e=le;et==null&&$e++<It.length;)M.has(It[$e])||(et=$e);if(Mt!=null||et!=null)if(Fe){let Zt=Mt==null?-1/0:z(Lt[Mt],P,ze,0),an=et==null?1/0:z(Lt[et],P,ze,0),Rn=lt-Zt,Ht=an-lt;Rn<=Ht?Rn<=Oe&&(be=Mt):Ht<=Oe&&(be=et)}else be=et==null?Mt:Mt==null?et:le-Mt<=et-le?Mt:et}else Fe&&Sn(lt-z(Lt[le],P,ze,0))>Oe&&(be=null);return be}}let tt=_=>{ce.event=_};ce.idxs=j,ce._lock=!1;let he=ce.points;he.show=Tt(he.show),he.size=Tt(he.size),he.stroke=Tt(he.stroke),he.width=Tt(he.width),he.fill=Tt(he.fill);let Ge=i.focus=_n({},n.focus||{alpha:.3},ce.focus),nt=Ge.prox>=0,Ie=nt&&he.one,dt=[],qt=[],zn=[];function ko(_,M){let I=he.show(i,M);if(I instanceof HTMLElement)return ri(I,vx),ri(I,_.class),Zi(I,-10,-10,O,Pe),g.insertBefore(I,dt[M]),I}function Dr(_,M){if(s==1||M>0){let I=s==1&&b[_.scale].time,N=_.value;_.value=I?am(N)?pm(W,dm(N,D)):N||q:N||Dy,_.label=_.label||(I?Ty:Ey)}if(Ie||M>0){_.width=_.width==null?1:_.width,_.paths=_.paths||$y||Bx,_.fillTo=Tt(_.fillTo||ky),_.pxAlign=+Pt(_.pxAlign,S),_.pxRound=Mm(_.pxAlign),_.stroke=Tt(_.stroke||null),_.fill=Tt(_.fill||null),_._stroke=_._fill=_._paths=_._focus=null;let I=Uy(Xn(1,_.width),1),N=_.points=_n({},{size:I,width:Xn(1,I*.2),stroke:_.stroke,space:I*2,paths:Zy,_stroke:null,_fill:null},_.points);N.show=Tt(N.show),N.filter=Tt(N.filter),N.fill=Tt(N.fill),N.stroke=Tt(N.stroke),N.paths=Tt(N.paths),N.pxAlign=_.pxAlign}if(ee){let I=at(_,M);it.splice(M,0,I[0]),We.splice(M,0,I[1]),ae.values.push(null)}if(pe){j.splice(M,0,null);let I=null;Ie?M==0&&(I=ko(_,M)):M>0&&(I=ko(_,M)),dt.splice(M,0,I),qt.splice(M,0,0),zn.splice(M,0,0)}An("addSeries",M)}function Yh(_,M){M=M??y.length,_=s==1?zu(_,M,gm,Sm):zu(_,M,{},vm),y.splice(M,0,_),Dr(y[M],M)}i.addSeries=Yh;function el(_){if(y.splice(_,1),ee){ae.values.splice(_,1),We.splice(_,1);let M=it.splice(_,1)[0];ft(null,M.firstChild),M.remove()}pe&&(j.splice(_,1),dt.splice(_,1)[0].remove(),qt.splice(_,1),zn.splice(_,1)),An("delSeries",_)}i.delSeries=el;let zi=[!1,!1,!1,!1];function ss(_,M){if(_._show=_.show,_.show){let I=_.side%2,N=b[_.scale];N==null&&(_.scale=I?y[1].scale:E,N=b[_.scale]);let V=N.time;_.size=Tt(_.size),_.space=Tt(_.space),_.rotate=Tt(_.rotate),Hs(_.incrs)&&_.incrs.forEach(le=>{!Vs.has(le)&&Vs.set(le,Om(le))}),_.incrs=Tt(_.incrs||(N.distr==2?oy:V?m==1?ly:uy:gr)),_.splits=Tt(_.splits||(V&&N.distr==1?te:N.distr==3?Ou:N.distr==4?Cy:Ry)),_.stroke=Tt(_.stroke),_.grid.stroke=Tt(_.grid.stroke),_.ticks.stroke=Tt(_.ticks.stroke),_.border.stroke=Tt(_.border.stroke);let J=_.values;_.values=Hs(J)&&!Hs(J[0])?Tt(J):V?Hs(J)?fm(W,um(J,D)):am(J)?py(W,J):J||X:J||Ay,_.filter=Tt(_.filter||(N.distr>=3&&N.log==10?Ly:N.distr==3&&N.log==2?Ny:Dm)),_.font=Am(_.font),_.labelFont=Am(_.labelFont),_._size=_.size(i,null,M,0),_._space=_._rotate=_._incrs=_._found=_._splits=_._values=null,_._size>0&&(zi[M]=!0,_._el=vi(gx,u))}}function rs(_,M,I,N){let[V,J,le,de]=I,be=M%2,Oe=0;return be==0&&(de||J)&&(Oe=M==0&&!V||M==2&&!le?vn(mm.size/3):0),be==1&&(V||le)&&(Oe=M==1&&!J||M==3&&!de?vn(xm.size/2):0),Oe}let zo=i.padding=(n.padding||[rs,rs,rs,rs]).map(_=>Tt(Pt(_,rs))),wi=i._padding=zo.map((_,M)=>_(i,M,zi,0)),rn,cn=null,hn=null,Gi=s==1?y[0].idxs:null,ei=null,As=!1;function Go(_,M){if(e=_??[],i.data=i._data=e,s==2){rn=0;for(let I=1;I<y.length;I++)rn+=e[I][0].length}else{e.length==0&&(i.data=i._data=e=[[]]),ei=e[0],rn=ei.length;let I=e;if(B==2){I=e.slice();let N=I[0]=Array(rn);for(let V=0;V<rn;V++)N[V]=V}i._data=e=I}if(mt(!0),An("setData"),B==2&&(Se=!0),M!==!1){let I=P;I.auto(i,As)?Ho():Is(E,I.min,I.max),ne=ne||ce.left>=0,me=!0,Un()}}i.setData=Go;function Ho(){As=!0;let _,M;s==1&&(rn>0?(cn=Gi[0]=0,hn=Gi[1]=rn-1,_=e[0][cn],M=e[0][hn],B==2?(_=cn,M=hn):_==M&&(B==3?[_,M]=Dl(_,_,P.log,!1):B==4?[_,M]=Wu(_,_,P.log,!1):P.time?M=_+vn(86400/m):[_,M]=Pl(_,M,Xu,!0))):(cn=Gi[0]=_=null,hn=Gi[1]=M=null)),Is(E,_,M)}let Ur,Rs,Or,w,G,Q,$,Z,Ae,Le;function Re(_,M,I,N,V,J){_??=Wp,I??=Yu,N??="butt",V??=Wp,J??="round",_!=Ur&&(f.strokeStyle=Ur=_),V!=Rs&&(f.fillStyle=Rs=V),M!=Or&&(f.lineWidth=Or=M),J!=G&&(f.lineJoin=G=J),N!=Q&&(f.lineCap=Q=N),I!=w&&f.setLineDash(w=I)}function De(_,M,I,N){M!=Rs&&(f.fillStyle=Rs=M),_!=$&&(f.font=$=_),I!=Z&&(f.textAlign=Z=I),N!=Ae&&(f.textBaseline=Ae=N)}function Ve(_,M,I,N,V=0){if(N.length>0&&_.auto(i,As)&&(M==null||M.min==null)){let J=Pt(cn,0),le=Pt(hn,N.length-1),de=I.min==null?Lx(N,J,le,V,_.distr==3):[I.min,I.max];_.min=Ii(_.min,I.min=de[0]),_.max=Xn(_.max,I.max=de[1])}}let st={min:null,max:null};function yt(){for(let N in b){let V=b[N];H[N]==null&&(V.min==null||H[E]!=null&&V.auto(i,As))&&(H[N]=st)}for(let N in b){let V=b[N];H[N]==null&&V.from!=null&&H[V.from]!=null&&(H[N]=st)}H[E]!=null&&mt(!0);let _={};for(let N in H){let V=H[N];if(V!=null){let J=_[N]=to(b[N],Gx);if(V.min!=null)_n(J,V);else if(N!=E||s==2)if(rn==0&&J.from==null){let le=J.range(i,null,null,N);J.min=le[0],J.max=le[1]}else J.min=Wt,J.max=-Wt}}if(rn>0){y.forEach((N,V)=>{if(s==1){let J=N.scale,le=H[J];if(le==null)return;let de=_[J];if(V==0){let be=de.range(i,de.min,de.max,J);de.min=be[0],de.max=be[1],cn=Ci(de.min,e[0]),hn=Ci(de.max,e[0]),hn-cn>1&&(e[0][cn]<de.min&&cn++,e[0][hn]>de.max&&hn--),N.min=ei[cn],N.max=ei[hn]}else N.show&&N.auto&&Ve(de,le,N,e[V],N.sorted);N.idxs[0]=cn,N.idxs[1]=hn}else if(V>0&&N.show&&N.auto){let[J,le]=N.facets,de=J.scale,be=le.scale,[Oe,Fe]=e[V],ze=_[de],lt=_[be];ze!=null&&Ve(ze,H[de],J,Oe,J.sorted),lt!=null&&Ve(lt,H[be],le,Fe,le.sorted),N.min=le.min,N.max=le.max}});for(let N in _){let V=_[N],J=H[N];if(V.from==null&&(J==null||J.min==null)){let le=V.range(i,V.min==Wt?null:V.min,V.max==-Wt?null:V.max,N);V.min=le[0],V.max=le[1]}}}for(let N in _){let V=_[N];if(V.from!=null){let J=_[V.from];if(J.min==null)V.min=V.max=null;else{let le=V.range(i,J.min,J.max,N);V.min=le[0],V.max=le[1]}}}let M={},I=!1;for(let N in _){let V=_[N],J=b[N];if(J.min!=V.min||J.max!=V.max){J.min=V.min,J.max=V.max;let le=J.distr;J._min=le==3?ds(J.min):le==4?Au(J.min,J.asinh):le==100?J.fwd(J.min):J.min,J._max=le==3?ds(J.max):le==4?Au(J.max,J.asinh):le==100?J.fwd(J.max):J.max,M[N]=I=!0}}if(I){y.forEach((N,V)=>{s==2?V>0&&M.y&&(N._paths=null):M[N.scale]&&(N._paths=null)});for(let N in M)Se=!0,An("setScale",N);pe&&ce.left>=0&&(ne=me=!0)}for(let N in H)H[N]=null}function He(_){let M=Uu(cn-1,0,rn-1),I=Uu(hn+1,0,rn-1);for(;_[M]==null&&M>0;)M--;for(;_[I]==null&&I<rn-1;)I++;return[M,I]}function vt(){if(rn>0){let _=y.some(M=>M._focus)&&Le!=Ge.alpha;_&&(f.globalAlpha=Le=Ge.alpha),y.forEach((M,I)=>{if(I>0&&M.show&&(tn(I,!1),tn(I,!0),M._paths==null)){let N=Le;Le!=M.alpha&&(f.globalAlpha=Le=M.alpha);let V=s==2?[0,e[I][0].length-1]:He(e[I]);M._paths=M.paths(i,I,V[0],V[1]),Le!=N&&(f.globalAlpha=Le=N)}}),y.forEach((M,I)=>{if(I>0&&M.show){let N=Le;Le!=M.alpha&&(f.globalAlpha=Le=M.alpha),M._paths!=null&&kt(I,!1);{let V=M._paths!=null?M._paths.gaps:null,J=M.points.show(i,I,cn,hn,V),le=M.points.filter(i,I,J,V);(J||le)&&(M.points._paths=M.points.paths(i,I,cn,hn,le),kt(I,!0))}Le!=N&&(f.globalAlpha=Le=N),An("drawSeries",I)}}),_&&(f.globalAlpha=Le=1)}}function tn(_,M){let I=M?y[_].points:y[_];I._stroke=I.stroke(i,_),I._fill=I.fill(i,_)}function kt(_,M){let I=M?y[_].points:y[_],{stroke:N,fill:V,clip:J,flags:le,_stroke:de=I._stroke,_fill:be=I._fill,_width:Oe=I.width}=I._paths;Oe=Xt(Oe*Nt,3);let Fe=null,ze=Oe%2/2;M&&be==null&&(be=Oe>0?"#fff":de);let lt=I.pxAlign==1&&ze>0;if(lt&&f.translate(ze,ze),!M){let Lt=R-Oe/2,It=v-Oe/2,Mt=Y+Oe,et=ue+Oe;Fe=new Path2D,Fe.rect(Lt,It,Mt,et)}M?ke(de,Oe,I.dash,I.cap,be,N,V,le,J):zt(_,de,Oe,I.dash,I.cap,be,N,V,le,Fe,J),lt&&f.translate(-ze,-ze)}function zt(_,M,I,N,V,J,le,de,be,Oe,Fe){let ze=!1;be!=0&&C.forEach((lt,Lt)=>{if(lt.series[0]==_){let It=y[lt.series[1]],Mt=e[lt.series[1]],et=(It._paths||ua).band;Hs(et)&&(et=lt.dir==1?et[0]:et[1]);let $e,Zt=null;It.show&&et&&Dx(Mt,cn,hn)?(Zt=lt.fill(i,Lt)||J,$e=It._paths.clip):et=null,ke(M,I,N,V,Zt,le,de,be,Oe,Fe,$e,et),ze=!0}}),ze||ke(M,I,N,V,J,le,de,be,Oe,Fe)}let yn=no|Bu;function ke(_,M,I,N,V,J,le,de,be,Oe,Fe,ze){Re(_,M,I,N,V),(be||Oe||ze)&&(f.save(),be&&f.clip(be),Oe&&f.clip(Oe)),ze?(de&yn)==yn?(f.clip(ze),Fe&&f.clip(Fe),Et(V,le),fn(_,J,M)):de&Bu?(Et(V,le),f.clip(ze),fn(_,J,M)):de&no&&(f.save(),f.clip(ze),Fe&&f.clip(Fe),Et(V,le),f.restore(),fn(_,J,M)):(Et(V,le),fn(_,J,M)),(be||Oe||ze)&&f.restore()}function fn(_,M,I){I>0&&(M instanceof Map?M.forEach((N,V)=>{f.strokeStyle=Ur=V,f.stroke(N)}):M!=null&&_&&f.stroke(M))}function Et(_,M){M instanceof Map?M.forEach((I,N)=>{f.fillStyle=Rs=N,f.fill(I)}):M!=null&&_&&f.fill(M)}function os(_,M,I,N){let V=A[_],J;if(N<=0)J=[0,0];else{let le=V._space=V.space(i,_,M,I,N),de=V._incrs=V.incrs(i,_,M,I,N,le);J=tv(M,I,de,N,le)}return V._found=J}function dn(_,M,I,N,V,J,le,de,be,Oe){let Fe=le%2/2;S==1&&f.translate(Fe,Fe),Re(de,le,be,Oe,de),f.beginPath();let ze,lt,Lt,It,Mt=V+(N==0||N==3?-J:J);I==0?(lt=V,It=Mt):(ze=V,Lt=Mt);for(let et=0;et<_.length;et++)M[et]!=null&&(I==0?ze=Lt=_[et]:lt=It=_[et],f.moveTo(ze,lt),f.lineTo(Lt,It));f.stroke(),S==1&&f.translate(-Fe,-Fe)}function Fr(_){let M=!0;return A.forEach((I,N)=>{if(!I.show)return;let V=b[I.scale];if(V.min==null){I._show&&(M=!1,I._show=!1,mt(!1));return}else I._show||(M=!1,I._show=!0,mt(!1));let J=I.side,le=J%2,{min:de,max:be}=V,[Oe,Fe]=os(N,de,be,le==0?O:Pe);if(Fe==0)return;let ze=V.distr==2,lt=I._splits=I.splits(i,N,de,be,Oe,Fe,ze),Lt=V.distr==2?lt.map($e=>ei[$e]):lt,It=V.distr==2?ei[lt[1]]-ei[lt[0]]:Oe,Mt=I._values=I.values(i,I.filter(i,Lt,N,Fe,It),N,Fe,It);I._rotate=J==2?I.rotate(i,Mt,N,Fe):0;let et=I._size;I._size=Si(I.size(i,Mt,N,_)),et!=null&&I._size!=et&&(M=!1)}),M}function Hi(_){let M=!0;return zo.forEach((I,N)=>{let V=I(i,N,zi,_);V!=wi[N]&&(M=!1),wi[N]=V}),M}function as(){for(let _=0;_<A.length;_++){let M=A[_];if(!M.show||!M._show)continue;let I=M.side,N=I%2,V,J,le=M.stroke(i,_),de=I==0||I==3?-1:1,[be,Oe]=M._found;if(M.label!=null){let Vn=M.labelGap*de,ii=vn((M._lpos+Vn)*Nt);De(M.labelFont[0],le,"center",I==2?"top":Vp),f.save(),N==1?(V=J=0,f.translate(ii,vn(v+ue/2)),f.rotate((I==3?-Cl:Cl)/2)):(V=vn(R+Y/2),J=ii);let ur=Lm(M.label)?M.label(i,_,be,Oe):M.label;f.fillText(ur,V,J),f.restore()}if(Oe==0)continue;let Fe=b[M.scale],ze=N==0?Y:ue,lt=N==0?R:v,Lt=M._splits,It=Fe.distr==2?Lt.map(Vn=>ei[Vn]):Lt,Mt=Fe.distr==2?ei[Lt[1]]-ei[Lt[0]]:be,et=M.ticks,$e=M.border,Zt=et.show?et.size:0,an=vn(Zt*Nt),Rn=vn((M.alignTo==2?M._size-Zt-M.gap:M.gap)*Nt),Ht=M._rotate*-Cl/180,ln=d(M._pos*Nt),ti=(an+Rn)*de,Hn=ln+ti;J=N==0?Hn:0,V=N==1?Hn:0;let _i=M.font[0],Ei=M.align==1?Kr:M.align==2?wu:Ht>0?Kr:Ht<0?wu:N==0?"center":I==3?wu:Kr,Xi=Ht||N==1?"middle":I==2?"top":Vp;De(_i,le,Ei,Xi);let ni=M.font[1]*M.lineGap,xi=Lt.map(Vn=>d(a(Vn,Fe,ze,lt))),Ti=M._values;for(let Vn=0;Vn<Ti.length;Vn++){let ii=Ti[Vn];if(ii!=null){N==0?V=xi[Vn]:J=xi[Vn],ii=""+ii;let ur=ii.indexOf(`
`)==-1?[ii]:ii.split(/\n/gm);for(let Wn=0;Wn<ur.length;Wn++){let jd=ur[Wn];Ht?(f.save(),f.translate(V,J+Wn*ni),f.rotate(Ht),f.fillText(jd,0,0),f.restore()):f.fillText(jd,V,J+Wn*ni)}}}et.show&&dn(xi,et.filter(i,It,_,Oe,Mt),N,I,ln,an,Xt(et.width*Nt,3),et.stroke(i,_),et.dash,et.cap);let qi=M.grid;qi.show&&dn(xi,qi.filter(i,It,_,Oe,Mt),N,N==0?2:1,N==0?v:R,N==0?ue:Y,Xt(qi.width*Nt,3),qi.stroke(i,_),qi.dash,qi.cap),$e.show&&dn([ln],[1],N==0?1:0,N==0?1:2,N==1?v:R,N==1?ue:Y,Xt($e.width*Nt,3),$e.stroke(i,_),$e.dash,$e.cap)}An("drawAxes")}function mt(_){y.forEach((M,I)=>{I>0&&(M._paths=null,_&&(s==1?(M.min=null,M.max=null):M.facets.forEach(N=>{N.min=null,N.max=null})))})}let on=!1,Gn=!1,Gt=[];function pn(){Gn=!1;for(let _=0;_<Gt.length;_++)An(...Gt[_]);Gt.length=0}function Un(){on||($x(Dd),on=!0)}function tl(_,M=!1){on=!0,Gn=M,_(i),Dd(),M&&Gt.length>0&&queueMicrotask(pn)}i.batch=tl;function Dd(){if(oe&&(yt(),oe=!1),Se&&(Te(),Se=!1),ve){if(Jt(p,Kr,je),Jt(p,"top",ht),Jt(p,aa,O),Jt(p,la,Pe),Jt(g,Kr,je),Jt(g,"top",ht),Jt(g,aa,O),Jt(g,la,Pe),Jt(u,aa,pt),Jt(u,la,bt),h.width=vn(pt*Nt),h.height=vn(bt*Nt),A.forEach(({_el:_,_show:M,_size:I,_pos:N,side:V})=>{if(_!=null)if(M){let J=V===3||V===0?I:0,le=V%2==1;Jt(_,le?"left":"top",N-J),Jt(_,le?"width":"height",I),Jt(_,le?"top":"left",le?ht:je),Jt(_,le?"height":"width",le?Pe:O),Nu(_,_r)}else ri(_,_r)}),Ur=Rs=Or=G=Q=$=Z=Ae=w=null,Le=1,Xo(!0),je!=Ee||ht!=Vt||O!=Xe||Pe!=Ke){mt(!1);let _=O/Xe,M=Pe/Ke;if(pe&&!ne&&ce.left>=0){ce.left*=_,ce.top*=M,Br&&Zi(Br,vn(ce.left),0,O,Pe),kr&&Zi(kr,0,vn(ce.top),O,Pe);for(let I=0;I<dt.length;I++){let N=dt[I];N!=null&&(qt[I]*=_,zn[I]*=M,Zi(N,Si(qt[I]),Si(zn[I]),O,Pe))}}if($t.show&&!se&&$t.left>=0&&$t.width>0){$t.left*=_,$t.width*=_,$t.top*=M,$t.height*=M;for(let I in Qh)Jt(Hr,I,$t[I])}Ee=je,Vt=ht,Xe=O,Ke=Pe}An("setSize"),ve=!1}pt>0&&bt>0&&(f.clearRect(0,0,h.width,h.height),An("drawClear"),T.forEach(_=>_()),An("draw")),$t.show&&se&&(nl($t),se=!1),pe&&ne&&(hr(null,!0,!1),ne=!1),ae.show&&ae.live&&me&&(Jh(),me=!1),l||(l=!0,i.status=1,An("ready")),As=!1,on=!1}i.redraw=(_,M)=>{Se=M||!1,_!==!1?Is(E,P.min,P.max):Un()};function $h(_,M){let I=b[_];if(I.from==null){if(rn==0){let N=I.range(i,M.min,M.max,_);M.min=N[0],M.max=N[1]}if(M.min>M.max){let N=M.min;M.min=M.max,M.max=N}if(rn>1&&M.min!=null&&M.max!=null&&M.max-M.min<1e-16)return;_==E&&I.distr==2&&rn>0&&(M.min=Ci(M.min,e[0]),M.max=Ci(M.max,e[0]),M.min==M.max&&M.max++),H[_]=M,oe=!0,Un()}}i.setScale=$h;let Zh,Kh,Br,kr,Ud,Od,zr,Gr,Fd,Bd,Yt,Qt,Cs=!1,Nn=ce.drag,En=Nn.x,Tn=Nn.y;pe&&(ce.x&&(Zh=vi(xx,g)),ce.y&&(Kh=vi(yx,g)),P.ori==0?(Br=Zh,kr=Kh):(Br=Kh,kr=Zh),Yt=ce.left,Qt=ce.top);let $t=i.select=_n({show:!0,over:!0,left:0,width:0,top:0,height:0},n.select),Hr=$t.show?vi(_x,$t.over?g:p):null;function nl(_,M){if($t.show){for(let I in _)$t[I]=_[I],I in Qh&&Jt(Hr,I,_[I]);M!==!1&&An("setSelect")}}i.setSelect=nl;function y_(_){if(y[_].show)ee&&Nu(it[_],_r);else if(ee&&ri(it[_],_r),pe){let I=Ie?dt[0]:dt[_];I!=null&&Zi(I,-10,-10,O,Pe)}}function Is(_,M,I){$h(_,{min:M,max:I})}function Vi(_,M,I,N){M.focus!=null&&w_(_),M.show!=null&&y.forEach((V,J)=>{J>0&&(_==J||_==null)&&(V.show=M.show,y_(J),s==2?(Is(V.facets[0].scale,null,null),Is(V.facets[1].scale,null,null)):Is(V.scale,null,null),Un())}),I!==!1&&An("setSeries",_,M),N&&qo("setSeries",i,_,M)}i.setSeries=Vi;function v_(_,M){_n(C[_],M)}function S_(_,M){_.fill=Tt(_.fill||null),_.dir=Pt(_.dir,-1),M=M??C.length,C.splice(M,0,_)}function b_(_){_==null?C.length=0:C.splice(_,1)}i.addBand=S_,i.setBand=v_,i.delBand=b_;function M_(_,M){y[_].alpha=M,pe&&dt[_]!=null&&(dt[_].style.opacity=M),ee&&it[_]&&(it[_].style.opacity=M)}let ls,Ps,cr,Vr={focus:!0};function w_(_){if(_!=cr){let M=_==null,I=Ge.alpha!=1;y.forEach((N,V)=>{if(s==1||V>0){let J=M||V==0||V==_;N._focus=M?null:J,I&&M_(V,J?1:Ge.alpha)}}),cr=_,I&&Un()}}ee&&nt&&Ze(Yp,Me,_=>{ce._lock||(tt(_),cr!=null&&Vi(null,Vr,!0,mn.setSeries))});function Wi(_,M,I){let N=b[M];I&&(_=_/Nt-(N.ori==1?ht:je));let V=O;N.ori==1&&(V=Pe,_=V-_),N.dir==-1&&(_=V-_);let J=N._min,le=N._max,de=_/V,be=J+(le-J)*de,Oe=N.distr;return Oe==3?Qr(10,be):Oe==4?Ox(be,N.asinh):Oe==100?N.bwd(be):be}function E_(_,M){let I=Wi(_,E,M);return Ci(I,e[0],cn,hn)}i.valToIdx=_=>Ci(_,e[0]),i.posToIdx=E_,i.posToVal=Wi,i.valToPos=(_,M,I)=>b[M].ori==0?r(_,b[M],I?Y:O,I?R:0):o(_,b[M],I?ue:Pe,I?v:0),i.setCursor=(_,M,I)=>{Yt=_.left,Qt=_.top,hr(null,M,I)};function kd(_,M){Jt(Hr,Kr,$t.left=_),Jt(Hr,aa,$t.width=M)}function zd(_,M){Jt(Hr,"top",$t.top=_),Jt(Hr,la,$t.height=M)}let Vo=P.ori==0?kd:zd,Wo=P.ori==1?kd:zd;function T_(){if(ee&&ae.live)for(let _=s==2?1:0;_<y.length;_++){if(_==0&&Ne)continue;let M=ae.values[_],I=0;for(let N in M)We[_][I++].firstChild.nodeValue=M[N]}}function Jh(_,M){if(_!=null&&(_.idxs?_.idxs.forEach((I,N)=>{j[N]=I}):zx(_.idx)||j.fill(_.idx),ae.idx=j[0]),ee&&ae.live){for(let I=0;I<y.length;I++)(I>0||s==1&&!Ne)&&A_(I,j[I]);T_()}me=!1,M!==!1&&An("setLegend")}i.setLegend=Jh;function A_(_,M){let I=y[_],N=_==0&&B==2?ei:e[_],V;Ne?V=I.values(i,_,M)??Be:(V=I.value(i,M==null?null:N[M],_,M),V=V==null?Be:{_:V}),ae.values[_]=V}function hr(_,M,I){Fd=Yt,Bd=Qt,[Yt,Qt]=ce.move(i,Yt,Qt),ce.left=Yt,ce.top=Qt,pe&&(Br&&Zi(Br,vn(Yt),0,O,Pe),kr&&Zi(kr,0,vn(Qt),O,Pe));let N,V=cn>hn;ls=Wt,Ps=null;let J=P.ori==0?O:Pe,le=P.ori==1?O:Pe;if(Yt<0||rn==0||V){N=ce.idx=null;for(let de=0;de<y.length;de++){let be=dt[de];be!=null&&Zi(be,-10,-10,O,Pe)}nt&&Vi(null,Vr,!0,_==null&&mn.setSeries),ae.live&&(j.fill(N),me=!0)}else{let de,be,Oe;s==1&&(de=P.ori==0?Yt:Qt,be=Wi(de,E),N=ce.idx=Ci(be,e[0],cn,hn),Oe=z(e[0][N],P,J,0));let Fe=-10,ze=-10,lt=0,Lt=0,It=!0,Mt="",et="";for(let $e=s==2?1:0;$e<y.length;$e++){let Zt=y[$e],an=j[$e],Rn=an==null?null:s==1?e[$e][an]:e[$e][1][an],Ht=ce.dataIdx(i,$e,N,be),ln=Ht==null?null:s==1?e[$e][Ht]:e[$e][1][Ht];if(me=me||ln!=Rn||Ht!=an,j[$e]=Ht,$e>0&&Zt.show){let ti=Ht==null?-10:Ht==N?Oe:z(s==1?e[0][Ht]:e[$e][0][Ht],P,J,0),Hn=ln==null?-10:L(ln,s==1?b[Zt.scale]:b[Zt.facets[1].scale],le,0);if(nt&&ln!=null){let _i=P.ori==1?Yt:Qt,Ei=Sn(Ge.dist(i,$e,Ht,Hn,_i));if(Ei<ls){let Xi=Ge.bias;if(Xi!=0){let ni=Wi(_i,Zt.scale),xi=ln>=0?1:-1,Ti=ni>=0?1:-1;Ti==xi&&(Ti==1?Xi==1?ln>=ni:ln<=ni:Xi==1?ln<=ni:ln>=ni)&&(ls=Ei,Ps=$e)}else ls=Ei,Ps=$e}}if(me||Ie){let _i,Ei;P.ori==0?(_i=ti,Ei=Hn):(_i=Hn,Ei=ti);let Xi,ni,xi,Ti,qi,Vn,ii=!0,ur=he.bbox;if(ur!=null){ii=!1;let Wn=ur(i,$e);xi=Wn.left,Ti=Wn.top,Xi=Wn.width,ni=Wn.height}else xi=_i,Ti=Ei,Xi=ni=he.size(i,$e);if(Vn=he.fill(i,$e),qi=he.stroke(i,$e),Ie)$e==Ps&&ls<=Ge.prox&&(Fe=xi,ze=Ti,lt=Xi,Lt=ni,It=ii,Mt=Vn,et=qi);else{let Wn=dt[$e];Wn!=null&&(qt[$e]=xi,zn[$e]=Ti,em(Wn,Xi,ni,ii),jp(Wn,Vn,qi),Zi(Wn,Si(xi),Si(Ti),O,Pe))}}}}if(Ie){let $e=Ge.prox,Zt=cr==null?ls<=$e:ls>$e||Ps!=cr;if(me||Zt){let an=dt[0];an!=null&&(qt[0]=Fe,zn[0]=ze,em(an,lt,Lt,It),jp(an,Mt,et),Zi(an,Si(Fe),Si(ze),O,Pe))}}}if($t.show&&Cs)if(_!=null){let[de,be]=mn.scales,[Oe,Fe]=mn.match,[ze,lt]=_.cursor.sync.scales,Lt=_.cursor.drag;if(En=Lt._x,Tn=Lt._y,En||Tn){let{left:It,top:Mt,width:et,height:$e}=_.select,Zt=_.scales[ze].ori,an=_.posToVal,Rn,Ht,ln,ti,Hn,_i=de!=null&&Oe(de,ze),Ei=be!=null&&Fe(be,lt);_i&&En?(Zt==0?(Rn=It,Ht=et):(Rn=Mt,Ht=$e),ln=b[de],ti=z(an(Rn,ze),ln,J,0),Hn=z(an(Rn+Ht,ze),ln,J,0),Vo(Ii(ti,Hn),Sn(Hn-ti))):Vo(0,J),Ei&&Tn?(Zt==1?(Rn=It,Ht=et):(Rn=Mt,Ht=$e),ln=b[be],ti=L(an(Rn,lt),ln,le,0),Hn=L(an(Rn+Ht,lt),ln,le,0),Wo(Ii(ti,Hn),Sn(Hn-ti))):Wo(0,le)}else eu()}else{let de=Sn(Fd-Ud),be=Sn(Bd-Od);if(P.ori==1){let lt=de;de=be,be=lt}En=Nn.x&&de>=Nn.dist,Tn=Nn.y&&be>=Nn.dist;let Oe=Nn.uni;Oe!=null?En&&Tn&&(En=de>=Oe,Tn=be>=Oe,!En&&!Tn&&(be>de?Tn=!0:En=!0)):Nn.x&&Nn.y&&(En||Tn)&&(En=Tn=!0);let Fe,ze;En&&(P.ori==0?(Fe=zr,ze=Yt):(Fe=Gr,ze=Qt),Vo(Ii(Fe,ze),Sn(ze-Fe)),Tn||Wo(0,le)),Tn&&(P.ori==1?(Fe=zr,ze=Yt):(Fe=Gr,ze=Qt),Wo(Ii(Fe,ze),Sn(ze-Fe)),En||Vo(0,J)),!En&&!Tn&&(Vo(0,0),Wo(0,0))}if(Nn._x=En,Nn._y=Tn,_==null){if(I){if(Jd!=null){let[de,be]=mn.scales;mn.values[0]=de!=null?Wi(P.ori==0?Yt:Qt,de):null,mn.values[1]=be!=null?Wi(P.ori==1?Yt:Qt,be):null}qo(Eu,i,Yt,Qt,O,Pe,N)}if(nt){let de=I&&mn.setSeries,be=Ge.prox;cr==null?ls<=be&&Vi(Ps,Vr,!0,de):ls>be?Vi(null,Vr,!0,de):Ps!=cr&&Vi(Ps,Vr,!0,de)}}me&&(ae.idx=N,Jh()),M!==!1&&An("setCursor")}let Ls=null;Object.defineProperty(i,"rect",{get(){return Ls==null&&Xo(!1),Ls}});function Xo(_=!1){_?Ls=null:(Ls=g.getBoundingClientRect(),An("syncRect",Ls))}function Gd(_,M,I,N,V,J,le){ce._lock||Cs&&_!=null&&_.movementX==0&&_.movementY==0||(jh(_,M,I,N,V,J,le,!1,_!=null),_!=null?hr(null,!0,!0):hr(M,!0,!1))}function jh(_,M,I,N,V,J,le,de,be){if(Ls==null&&Xo(!1),tt(_),_!=null)I=_.clientX-Ls.left,N=_.clientY-Ls.top;else{if(I<0||N<0){Yt=-10,Qt=-10;return}let[Oe,Fe]=mn.scales,ze=M.cursor.sync,[lt,Lt]=ze.values,[It,Mt]=ze.scales,[et,$e]=mn.match,Zt=M.axes[0].side%2==1,an=P.ori==0?O:Pe,Rn=P.ori==1?O:Pe,Ht=Zt?J:V,ln=Zt?V:J,ti=Zt?N:I,Hn=Zt?I:N;if(It!=null?I=et(Oe,It)?a(lt,b[Oe],an,0):-10:I=an*(ti/Ht),Mt!=null?N=$e(Fe,Mt)?a(Lt,b[Fe],Rn,0):-10:N=Rn*(Hn/ln),P.ori==1){let _i=I;I=N,N=_i}}be&&(M==null||M.cursor.event.type==Eu)&&((I<=1||I>=O-1)&&(I=mr(I,O)),(N<=1||N>=Pe-1)&&(N=mr(N,Pe))),de?(Ud=I,Od=N,[zr,Gr]=ce.move(i,I,N)):(Yt=I,Qt=N)}let Qh={width:0,height:0,left:0,top:0};function eu(){nl(Qh,!1)}let Hd,Vd,Wd,Xd;function qd(_,M,I,N,V,J,le){Cs=!0,En=Tn=Nn._x=Nn._y=!1,jh(_,M,I,N,V,J,le,!0,!1),_!=null&&(Ze(Tu,Pu,Yd,!1),qo(Xp,i,zr,Gr,O,Pe,null));let{left:de,top:be,width:Oe,height:Fe}=$t;Hd=de,Vd=be,Wd=Oe,Xd=Fe}function Yd(_,M,I,N,V,J,le){Cs=Nn._x=Nn._y=!1,jh(_,M,I,N,V,J,le,!1,!0);let{left:de,top:be,width:Oe,height:Fe}=$t,ze=Oe>0||Fe>0,lt=Hd!=de||Vd!=be||Wd!=Oe||Xd!=Fe;if(ze&&lt&&nl($t),Nn.setScale&&ze&&lt){let Lt=de,It=Oe,Mt=be,et=Fe;if(P.ori==1&&(Lt=be,It=Fe,Mt=de,et=Oe),En&&Is(E,Wi(Lt,E),Wi(Lt+It,E)),Tn)for(let $e in b){let Zt=b[$e];$e!=E&&Zt.from==null&&Zt.min!=Wt&&Is($e,Wi(Mt+et,$e),Wi(Mt,$e))}eu()}else ce.lock&&(ce._lock=!ce._lock,hr(M,!0,_!=null));_!=null&&(ft(Tu,Pu),qo(Tu,i,Yt,Qt,O,Pe,null))}function R_(_,M,I,N,V,J,le){if(ce._lock)return;tt(_);let de=Cs;if(Cs){let be=!0,Oe=!0,Fe=10,ze,lt;P.ori==0?(ze=En,lt=Tn):(ze=Tn,lt=En),ze&&lt&&(be=Yt<=Fe||Yt>=O-Fe,Oe=Qt<=Fe||Qt>=Pe-Fe),ze&&be&&(Yt=Yt<zr?0:O),lt&&Oe&&(Qt=Qt<Gr?0:Pe),hr(null,!0,!0),Cs=!1}Yt=-10,Qt=-10,j.fill(null),hr(null,!0,!0),de&&(Cs=de)}function $d(_,M,I,N,V,J,le){ce._lock||(tt(_),Ho(),eu(),_!=null&&qo($p,i,Yt,Qt,O,Pe,null))}function Zd(){A.forEach(nv),F(i.width,i.height,!0)}xr(Il,jr,Zd);let Wr={};Wr.mousedown=qd,Wr.mousemove=Gd,Wr.mouseup=Yd,Wr.dblclick=$d,Wr.setSeries=(_,M,I,N)=>{let V=mn.match[2];I=V(i,M,I),I!=-1&&Vi(I,N,!0,!1)},pe&&(Ze(Xp,g,qd),Ze(Eu,g,Gd),Ze(qp,g,_=>{tt(_),Xo(!1)}),Ze(Yp,g,R_),Ze($p,g,$d),ku.add(i),i.syncRect=Xo);let il=i.hooks=n.hooks||{};function An(_,M,I){Gn?Gt.push([_,M,I]):_ in il&&il[_].forEach(N=>{N.call(null,i,M,I)})}(n.plugins||[]).forEach(_=>{for(let M in _.hooks)il[M]=(il[M]||[]).concat(_.hooks[M])});let Kd=(_,M,I)=>I,mn=_n({key:null,setSeries:!1,filters:{pub:rm,sub:rm},scales:[E,y[1]?y[1].scale:null],match:[om,om,Kd],values:[null,null]},ce.sync);mn.match.length==2&&mn.match.push(Kd),ce.sync=mn;let Jd=mn.key,tu=ng(Jd);function qo(_,M,I,N,V,J,le){mn.filters.pub(_,M,I,N,V,J,le)&&tu.pub(_,M,I,N,V,J,le)}tu.sub(i);function C_(_,M,I,N,V,J,le){mn.filters.sub(_,M,I,N,V,J,le)&&Wr[_](null,M,I,N,V,J,le)}i.pub=C_;function I_(){tu.unsub(i),ku.delete(i),Ct.clear(),Du(Il,jr,Zd),c.remove(),Me?.remove(),An("destroy")}i.destroy=I_;function nu(){An("init",n,e),Go(e||n.data,!1),H[E]?$h(E,H[E]):Ho(),se=$t.show&&($t.width>0||$t.height>0),ne=me=!0,F(n.width,n.height)}return y.forEach(Dr),A.forEach(ss),t?t instanceof HTMLElement?(t.appendChild(c),nu()):t(i,nu):nu(),i}Cn.assign=_n;Cn.fmtNum=qu;Cn.rangeNum=Pl;Cn.rangeLog=Dl;Cn.rangeAsinh=Wu;Cn.orient=vr;Cn.pxRatio=Nt;Cn.join=Yx;Cn.fmtDate=$u,Cn.tzDate=sy;Cn.sync=ng;{Cn.addGap=zy,Cn.clipGaps=Fl;let n=Cn.paths={points:lg};n.linear=hg,n.stepped=Vy,n.bars=Wy,n.spline=qy}var Sr=class{constructor(e,t){this.keep=t;this.ys=Array.from({length:e},()=>[])}keep;t=[];ys;push(e,...t){if(this.t.push(e),t.forEach((i,s)=>this.ys[s].push(i!=null&&Number.isFinite(i)?i:null)),this.t.length>this.keep){this.t.shift();for(let i of this.ys)i.shift()}}},oo=class{constructor(e,t,i,s=120,r=28){this.s=t;let o=document.createElement("span");o.className="spark",e.appendChild(o),this.plot=new Cn({width:s,height:r,cursor:{show:!1},legend:{show:!1},select:{show:!1},axes:[{show:!1},{show:!1}],scales:{x:{time:!1},y:{range:(a,l,c)=>[Math.min(0,l),c>0?c*1.1:1]}},series:[{},{stroke:i,width:1.5,fill:i+"33",points:{show:!1}}]},[[],[]],o),o.appendChild(this.label)}s;plot;label=document.createElement("span");update(e){this.plot.setData([this.s.t,this.s.ys[0]]),this.label.textContent=e}destroy(){this.plot.destroy()}},Gl=class{constructor(e,t,i,s,r){this.s=t;this.plot=new Cn({width:s,height:r,scales:{x:{time:!0}},axes:[{stroke:"#8a96a3",grid:{stroke:"#1f2a35"}},{stroke:"#8a96a3",grid:{stroke:"#1f2a35"},scale:i[0].scale},...i.some(o=>o.scale==="r")?[{side:1,scale:"r",stroke:"#8a96a3",grid:{show:!1}}]:[]],series:[{},...i.map(o=>({label:o.label,stroke:o.colour,width:1.5,scale:o.scale,points:{show:!1}}))]},[[],...i.map(()=>[])],e)}s;plot;update(){this.plot.setData([this.s.t,...this.s.ys])}destroy(){this.plot.destroy()}};var ir={LEFT:0,MIDDLE:1,RIGHT:2,ROTATE:0,DOLLY:1,PAN:2},sr={ROTATE:0,PAN:1,DOLLY_PAN:2,DOLLY_ROTATE:3},Hg=0,Cf=1,Vg=2;var Ha=1,Wg=2,Lo=3,rr=0,$n=1,es=2,Rr=0,No=1,If=2,Pf=3,Lf=4,Xg=5;var Cr=100,qg=101,Yg=102,$g=103,Zg=104,Kg=200,Jg=201,jg=202,Qg=203,Nf=204,Df=205,e0=206,t0=207,n0=208,i0=209,s0=210,r0=211,o0=212,a0=213,l0=214,pc=0,mc=1,gc=2,bo=3,_c=4,xc=5,yc=6,vc=7,Uf=0,c0=1,h0=2,ts=0,Of=1,Ff=2,Bf=3,kf=4,zf=5,Gf=6,Hf=7;var Vf=300,Ir=301,Do=302,Zc=303,Kc=304,Sc=1e3,Ji=1001,bc=1002,Ln=1003,u0=1004;var Va=1005;var Yn=1006,Jc=1007;var ws=1008;var gi=1009,Wf=1010,Xf=1011,Uo=1012,jc=1013,Ui=1014,Oi=1015,Fi=1016,Qc=1017,eh=1018,Pr=1020,qf=35902,Yf=35899,$f=1021,Zf=1022,Bi=1023,Ss=1026,Es=1027,Kf=1028,th=1029,or=1030,nh=1031;var ih=1033,Wa=33776,Xa=33777,qa=33778,Ya=33779,sh=35840,rh=35841,oh=35842,ah=35843,lh=36196,ch=37492,hh=37496,uh=37488,fh=37489,$a=37490,dh=37491,ph=37808,mh=37809,gh=37810,_h=37811,xh=37812,yh=37813,vh=37814,Sh=37815,bh=37816,Mh=37817,wh=37818,Eh=37819,Th=37820,Ah=37821,Rh=36492,Ch=36494,Ih=36495,Ph=36283,Lh=36284,Za=36285,Nh=36286;var Sa=2300,Mc=2301,fc=2302,bf=2303,Mf=2400,wf=2401,Ef=2402;var f0=3200;var Jf=0,d0=1,Ts="",hi="srgb",ba="srgb-linear",Ma="linear",Ft="srgb";var dc=7680;var p0=519,m0=512,g0=513,_0=514,jf=515,x0=516,y0=517,Qf=518,ed=519,v0=35044;var td="300 es",Mi=2e3,wa=2001;function iv(n){for(let e=n.length-1;e>=0;--e)if(n[e]>=65535)return!0;return!1}function sv(n){return ArrayBuffer.isView(n)&&!(n instanceof DataView)}function Ea(n){return document.createElementNS("http://www.w3.org/1999/xhtml",n)}function S0(){let n=Ea("canvas");return n.style.display="block",n}var pg={},Mo=null;function nd(...n){let e="THREE."+n.shift();Mo?Mo("log",e,...n):console.log(e,...n)}function b0(n){let e=n[0];if(typeof e=="string"&&e.startsWith("TSL:")){let t=n[1];t&&t.isStackTrace?n[0]+=" "+t.getLocation():n[1]='Stack trace not available. Enable "THREE.Node.captureStackTrace" to capture stack traces.'}return n}function Je(...n){n=b0(n);let e="THREE."+n.shift();if(Mo)Mo("warn",e,...n);else{let t=n[0];t&&t.isStackTrace?console.warn(t.getError(e)):console.warn(e,...n)}}function rt(...n){n=b0(n);let e="THREE."+n.shift();if(Mo)Mo("error",e,...n);else{let t=n[0];t&&t.isStackTrace?console.error(t.getError(e)):console.error(e,...n)}}function xa(...n){let e=n.join(" ");e in pg||(pg[e]=!0,Je(...n))}function M0(n,e,t){return new Promise(function(i,s){function r(){switch(n.clientWaitSync(e,n.SYNC_FLUSH_COMMANDS_BIT,0)){case n.WAIT_FAILED:s();break;case n.TIMEOUT_EXPIRED:setTimeout(r,t);break;default:i()}}setTimeout(r,t)})}var w0={[pc]:pc,[gc]:yc,[_c]:_c,[bo]:xc,[mc]:mc,[yc]:gc,[vc]:vc,[xc]:bo},Di=class{addEventListener(e,t){this._listeners===void 0&&(this._listeners={});let i=this._listeners;i[e]===void 0&&(i[e]=[]),i[e].indexOf(t)===-1&&i[e].push(t)}hasEventListener(e,t){let i=this._listeners;return i===void 0?!1:i[e]!==void 0&&i[e].indexOf(t)!==-1}removeEventListener(e,t){let i=this._listeners;if(i===void 0)return;let s=i[e];if(s!==void 0){let r=s.indexOf(t);r!==-1&&s.splice(r,1)}}dispatchEvent(e){let t=this._listeners;if(t===void 0)return;let i=t[e.type];if(i!==void 0){e.target=this;let s=i.slice(0);for(let r=0,o=s.length;r<o;r++)s[r].call(this,e);e.target=null}}},Fn=["00","01","02","03","04","05","06","07","08","09","0a","0b","0c","0d","0e","0f","10","11","12","13","14","15","16","17","18","19","1a","1b","1c","1d","1e","1f","20","21","22","23","24","25","26","27","28","29","2a","2b","2c","2d","2e","2f","30","31","32","33","34","35","36","37","38","39","3a","3b","3c","3d","3e","3f","40","41","42","43","44","45","46","47","48","49","4a","4b","4c","4d","4e","4f","50","51","52","53","54","55","56","57","58","59","5a","5b","5c","5d","5e","5f","60","61","62","63","64","65","66","67","68","69","6a","6b","6c","6d","6e","6f","70","71","72","73","74","75","76","77","78","79","7a","7b","7c","7d","7e","7f","80","81","82","83","84","85","86","87","88","89","8a","8b","8c","8d","8e","8f","90","91","92","93","94","95","96","97","98","99","9a","9b","9c","9d","9e","9f","a0","a1","a2","a3","a4","a5","a6","a7","a8","a9","aa","ab","ac","ad","ae","af","b0","b1","b2","b3","b4","b5","b6","b7","b8","b9","ba","bb","bc","bd","be","bf","c0","c1","c2","c3","c4","c5","c6","c7","c8","c9","ca","cb","cc","cd","ce","cf","d0","d1","d2","d3","d4","d5","d6","d7","d8","d9","da","db","dc","dd","de","df","e0","e1","e2","e3","e4","e5","e6","e7","e8","e9","ea","eb","ec","ed","ee","ef","f0","f1","f2","f3","f4","f5","f6","f7","f8","f9","fa","fb","fc","fd","fe","ff"],mg=1234567,ya=Math.PI/180,wo=180/Math.PI;function Oo(){let n=Math.random()*4294967295|0,e=Math.random()*4294967295|0,t=Math.random()*4294967295|0,i=Math.random()*4294967295|0;return(Fn[n&255]+Fn[n>>8&255]+Fn[n>>16&255]+Fn[n>>24&255]+"-"+Fn[e&255]+Fn[e>>8&255]+"-"+Fn[e>>16&15|64]+Fn[e>>24&255]+"-"+Fn[t&63|128]+Fn[t>>8&255]+"-"+Fn[t>>16&255]+Fn[t>>24&255]+Fn[i&255]+Fn[i>>8&255]+Fn[i>>16&255]+Fn[i>>24&255]).toLowerCase()}function St(n,e,t){return Math.max(e,Math.min(t,n))}function id(n,e){return(n%e+e)%e}function rv(n,e,t,i,s){return i+(n-e)*(s-i)/(t-e)}function ov(n,e,t){return n!==e?(t-n)/(e-n):0}function va(n,e,t){return(1-t)*n+t*e}function av(n,e,t,i){return va(n,e,1-Math.exp(-t*i))}function lv(n,e=1){return e-Math.abs(id(n,e*2)-e)}function cv(n,e,t){return n<=e?0:n>=t?1:(n=(n-e)/(t-e),n*n*(3-2*n))}function hv(n,e,t){return n<=e?0:n>=t?1:(n=(n-e)/(t-e),n*n*n*(n*(n*6-15)+10))}function uv(n,e){return n+Math.floor(Math.random()*(e-n+1))}function fv(n,e){return n+Math.random()*(e-n)}function dv(n){return n*(.5-Math.random())}function pv(n){n!==void 0&&(mg=n);let e=mg+=1831565813;return e=Math.imul(e^e>>>15,e|1),e^=e+Math.imul(e^e>>>7,e|61),((e^e>>>14)>>>0)/4294967296}function mv(n){return n*ya}function gv(n){return n*wo}function _v(n){return n>0&&Number.isInteger(n)&&2**Math.round(Math.log2(n))===n}function xv(n){return Math.pow(2,Math.ceil(Math.log(n)/Math.LN2))}function sd(n){return Math.pow(2,Math.floor(Math.log(n)/Math.LN2))}function yv(n,e,t,i,s){let r=Math.cos,o=Math.sin,a=r(t/2),l=o(t/2),c=r((e+i)/2),h=o((e+i)/2),f=r((e-i)/2),u=o((e-i)/2),p=r((i-e)/2),g=o((i-e)/2);switch(s){case"XYX":n.set(a*h,l*f,l*u,a*c);break;case"YZY":n.set(l*u,a*h,l*f,a*c);break;case"ZXZ":n.set(l*f,l*u,a*h,a*c);break;case"XZX":n.set(a*h,l*g,l*p,a*c);break;case"YXY":n.set(l*p,a*h,l*g,a*c);break;case"ZYZ":n.set(l*g,l*p,a*h,a*c);break;default:Je("MathUtils: .setQuaternionFromProperEuler() encountered an unknown order: "+s)}}function rd(n){switch(n.constructor){case Uint32Array:return 4294967295;case Uint16Array:return 65535;case Uint8Array:case Uint8ClampedArray:return 255;case Int32Array:return 2147483647;case Int16Array:return 32767;case Int8Array:return 127;default:return}}function E0(n,e){if(e.constructor===Float32Array)return n;let t=rd(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.max(n/t,-1)}function T0(n,e){if(e.constructor===Float32Array)return n;let t=rd(e);if(t===void 0)throw new Error("THREE.MathUtils: Invalid component type.");return Math.round(n*t)}var od={DEG2RAD:ya,RAD2DEG:wo,generateUUID:Oo,clamp:St,euclideanModulo:id,mapLinear:rv,inverseLerp:ov,lerp:va,damp:av,pingpong:lv,smoothstep:cv,smootherstep:hv,randInt:uv,randFloat:fv,randFloatSpread:dv,seededRandom:pv,degToRad:mv,radToDeg:gv,isPowerOfTwo:_v,ceilPowerOfTwo:xv,floorPowerOfTwo:sd,setQuaternionFromProperEuler:yv,normalize:T0,denormalize:E0},ud=class ud{constructor(e=0,t=0){this.x=e,this.y=t}get width(){return this.x}set width(e){this.x=e}get height(){return this.y}set height(e){this.y=e}set(e,t){return this.x=e,this.y=t,this}setScalar(e){return this.x=e,this.y=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;default:throw new Error("THREE.Vector2: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;default:throw new Error("THREE.Vector2: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y)}copy(e){return this.x=e.x,this.y=e.y,this}add(e){return this.x+=e.x,this.y+=e.y,this}addScalar(e){return this.x+=e,this.y+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this}subScalar(e){return this.x-=e,this.y-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this}multiply(e){return this.x*=e.x,this.y*=e.y,this}multiplyScalar(e){return this.x*=e,this.y*=e,this}divide(e){return this.x/=e.x,this.y/=e.y,this}divideScalar(e){return this.multiplyScalar(1/e)}applyMatrix3(e){let t=this.x,i=this.y,s=e.elements;return this.x=s[0]*t+s[3]*i+s[6],this.y=s[1]*t+s[4]*i+s[7],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this}clamp(e,t){return this.x=St(this.x,e.x,t.x),this.y=St(this.y,e.y,t.y),this}clampScalar(e,t){return this.x=St(this.x,e,t),this.y=St(this.y,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(St(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this}negate(){return this.x=-this.x,this.y=-this.y,this}dot(e){return this.x*e.x+this.y*e.y}cross(e){return this.x*e.y-this.y*e.x}lengthSq(){return this.x*this.x+this.y*this.y}length(){return Math.sqrt(this.x*this.x+this.y*this.y)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)}normalize(){return this.divideScalar(this.length()||1)}angle(){return Math.atan2(-this.y,-this.x)+Math.PI}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let i=this.dot(e)/t;return Math.acos(St(i,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,i=this.y-e.y;return t*t+i*i}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this}equals(e){return e.x===this.x&&e.y===this.y}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this}rotateAround(e,t){let i=Math.cos(t),s=Math.sin(t),r=this.x-e.x,o=this.y-e.y;return this.x=r*i-o*s+e.x,this.y=r*s+o*i+e.y,this}random(){return this.x=Math.random(),this.y=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y}};ud.prototype.isVector2=!0;var ut=ud,di=class{constructor(e=0,t=0,i=0,s=1){this.isQuaternion=!0,this._x=e,this._y=t,this._z=i,this._w=s}static slerpFlat(e,t,i,s,r,o,a){let l=i[s+0],c=i[s+1],h=i[s+2],f=i[s+3],u=r[o+0],p=r[o+1],g=r[o+2],S=r[o+3];if(f!==S||l!==u||c!==p||h!==g){let d=l*u+c*p+h*g+f*S;d<0&&(u=-u,p=-p,g=-g,S=-S,d=-d);let m=1-a;if(d<.9995){let y=Math.acos(d),A=Math.sin(y);m=Math.sin(m*y)/A,a=Math.sin(a*y)/A,l=l*m+u*a,c=c*m+p*a,h=h*m+g*a,f=f*m+S*a}else{l=l*m+u*a,c=c*m+p*a,h=h*m+g*a,f=f*m+S*a;let y=1/Math.sqrt(l*l+c*c+h*h+f*f);l*=y,c*=y,h*=y,f*=y}}e[t]=l,e[t+1]=c,e[t+2]=h,e[t+3]=f}static multiplyQuaternionsFlat(e,t,i,s,r,o){let a=i[s],l=i[s+1],c=i[s+2],h=i[s+3],f=r[o],u=r[o+1],p=r[o+2],g=r[o+3];return e[t]=a*g+h*f+l*p-c*u,e[t+1]=l*g+h*u+c*f-a*p,e[t+2]=c*g+h*p+a*u-l*f,e[t+3]=h*g-a*f-l*u-c*p,e}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get w(){return this._w}set w(e){this._w=e,this._onChangeCallback()}set(e,t,i,s){return this._x=e,this._y=t,this._z=i,this._w=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._w)}copy(e){return this._x=e.x,this._y=e.y,this._z=e.z,this._w=e.w,this._onChangeCallback(),this}setFromEuler(e,t=!0){let i=e._x,s=e._y,r=e._z,o=e._order,a=Math.cos,l=Math.sin,c=a(i/2),h=a(s/2),f=a(r/2),u=l(i/2),p=l(s/2),g=l(r/2);switch(o){case"XYZ":this._x=u*h*f+c*p*g,this._y=c*p*f-u*h*g,this._z=c*h*g+u*p*f,this._w=c*h*f-u*p*g;break;case"YXZ":this._x=u*h*f+c*p*g,this._y=c*p*f-u*h*g,this._z=c*h*g-u*p*f,this._w=c*h*f+u*p*g;break;case"ZXY":this._x=u*h*f-c*p*g,this._y=c*p*f+u*h*g,this._z=c*h*g+u*p*f,this._w=c*h*f-u*p*g;break;case"ZYX":this._x=u*h*f-c*p*g,this._y=c*p*f+u*h*g,this._z=c*h*g-u*p*f,this._w=c*h*f+u*p*g;break;case"YZX":this._x=u*h*f+c*p*g,this._y=c*p*f+u*h*g,this._z=c*h*g-u*p*f,this._w=c*h*f-u*p*g;break;case"XZY":this._x=u*h*f-c*p*g,this._y=c*p*f-u*h*g,this._z=c*h*g+u*p*f,this._w=c*h*f+u*p*g;break;default:Je("Quaternion: .setFromEuler() encountered an unknown order: "+o)}return t===!0&&this._onChangeCallback(),this}setFromAxisAngle(e,t){let i=t/2,s=Math.sin(i);return this._x=e.x*s,this._y=e.y*s,this._z=e.z*s,this._w=Math.cos(i),this._onChangeCallback(),this}setFromRotationMatrix(e){let t=e.elements,i=t[0],s=t[4],r=t[8],o=t[1],a=t[5],l=t[9],c=t[2],h=t[6],f=t[10],u=i+a+f;if(u>0){let p=.5/Math.sqrt(u+1);this._w=.25/p,this._x=(h-l)*p,this._y=(r-c)*p,this._z=(o-s)*p}else if(i>a&&i>f){let p=2*Math.sqrt(1+i-a-f);this._w=(h-l)/p,this._x=.25*p,this._y=(s+o)/p,this._z=(r+c)/p}else if(a>f){let p=2*Math.sqrt(1+a-i-f);this._w=(r-c)/p,this._x=(s+o)/p,this._y=.25*p,this._z=(l+h)/p}else{let p=2*Math.sqrt(1+f-i-a);this._w=(o-s)/p,this._x=(r+c)/p,this._y=(l+h)/p,this._z=.25*p}return this._onChangeCallback(),this}setFromUnitVectors(e,t){let i=e.dot(t)+1;return i<1e-8?(i=0,Math.abs(e.x)>Math.abs(e.z)?(this._x=-e.y,this._y=e.x,this._z=0,this._w=i):(this._x=0,this._y=-e.z,this._z=e.y,this._w=i)):(this._x=e.y*t.z-e.z*t.y,this._y=e.z*t.x-e.x*t.z,this._z=e.x*t.y-e.y*t.x,this._w=i),this.normalize()}angleTo(e){return 2*Math.acos(Math.abs(St(this.dot(e),-1,1)))}rotateTowards(e,t){let i=this.angleTo(e);if(i===0)return this;let s=Math.min(1,t/i);return this.slerp(e,s),this}identity(){return this.set(0,0,0,1)}invert(){return this.conjugate()}conjugate(){return this._x*=-1,this._y*=-1,this._z*=-1,this._onChangeCallback(),this}dot(e){return this._x*e._x+this._y*e._y+this._z*e._z+this._w*e._w}lengthSq(){return this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w}length(){return Math.sqrt(this._x*this._x+this._y*this._y+this._z*this._z+this._w*this._w)}normalize(){let e=this.length();return e===0?(this._x=0,this._y=0,this._z=0,this._w=1):(e=1/e,this._x=this._x*e,this._y=this._y*e,this._z=this._z*e,this._w=this._w*e),this._onChangeCallback(),this}multiply(e){return this.multiplyQuaternions(this,e)}premultiply(e){return this.multiplyQuaternions(e,this)}multiplyQuaternions(e,t){let i=e._x,s=e._y,r=e._z,o=e._w,a=t._x,l=t._y,c=t._z,h=t._w;return this._x=i*h+o*a+s*c-r*l,this._y=s*h+o*l+r*a-i*c,this._z=r*h+o*c+i*l-s*a,this._w=o*h-i*a-s*l-r*c,this._onChangeCallback(),this}slerp(e,t){let i=e._x,s=e._y,r=e._z,o=e._w,a=this.dot(e);a<0&&(i=-i,s=-s,r=-r,o=-o,a=-a);let l=1-t;if(a<.9995){let c=Math.acos(a),h=Math.sin(c);l=Math.sin(l*c)/h,t=Math.sin(t*c)/h,this._x=this._x*l+i*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+o*t,this._onChangeCallback()}else this._x=this._x*l+i*t,this._y=this._y*l+s*t,this._z=this._z*l+r*t,this._w=this._w*l+o*t,this.normalize();return this}slerpQuaternions(e,t,i){return this.copy(e).slerp(t,i)}random(){let e=2*Math.PI*Math.random(),t=2*Math.PI*Math.random(),i=Math.random(),s=Math.sqrt(1-i),r=Math.sqrt(i);return this.set(s*Math.sin(e),s*Math.cos(e),r*Math.sin(t),r*Math.cos(t))}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._w===this._w}fromArray(e,t=0){return this._x=e[t],this._y=e[t+1],this._z=e[t+2],this._w=e[t+3],this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._w,e}fromBufferAttribute(e,t){return this._x=e.getX(t),this._y=e.getY(t),this._z=e.getZ(t),this._w=e.getW(t),this._onChangeCallback(),this}toJSON(){return this.toArray()}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._w}},fd=class fd{constructor(e=0,t=0,i=0){this.x=e,this.y=t,this.z=i}set(e,t,i){return i===void 0&&(i=this.z),this.x=e,this.y=t,this.z=i,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;default:throw new Error("THREE.Vector3: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;default:throw new Error("THREE.Vector3: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this}multiplyVectors(e,t){return this.x=e.x*t.x,this.y=e.y*t.y,this.z=e.z*t.z,this}applyEuler(e){return this.applyQuaternion(gg.setFromEuler(e))}applyAxisAngle(e,t){return this.applyQuaternion(gg.setFromAxisAngle(e,t))}applyMatrix3(e){let t=this.x,i=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[3]*i+r[6]*s,this.y=r[1]*t+r[4]*i+r[7]*s,this.z=r[2]*t+r[5]*i+r[8]*s,this}applyNormalMatrix(e){return this.applyMatrix3(e).normalize()}applyMatrix4(e){let t=this.x,i=this.y,s=this.z,r=e.elements,o=1/(r[3]*t+r[7]*i+r[11]*s+r[15]);return this.x=(r[0]*t+r[4]*i+r[8]*s+r[12])*o,this.y=(r[1]*t+r[5]*i+r[9]*s+r[13])*o,this.z=(r[2]*t+r[6]*i+r[10]*s+r[14])*o,this}applyQuaternion(e){let t=this.x,i=this.y,s=this.z,r=e.x,o=e.y,a=e.z,l=e.w,c=2*(o*s-a*i),h=2*(a*t-r*s),f=2*(r*i-o*t);return this.x=t+l*c+o*f-a*h,this.y=i+l*h+a*c-r*f,this.z=s+l*f+r*h-o*c,this}project(e){return this.applyMatrix4(e.matrixWorldInverse).applyMatrix4(e.projectionMatrix)}unproject(e){return this.applyMatrix4(e.projectionMatrixInverse).applyMatrix4(e.matrixWorld)}transformDirection(e){let t=this.x,i=this.y,s=this.z,r=e.elements;return this.x=r[0]*t+r[4]*i+r[8]*s,this.y=r[1]*t+r[5]*i+r[9]*s,this.z=r[2]*t+r[6]*i+r[10]*s,this.normalize()}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this}divideScalar(e){return this.multiplyScalar(1/e)}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this}clamp(e,t){return this.x=St(this.x,e.x,t.x),this.y=St(this.y,e.y,t.y),this.z=St(this.z,e.z,t.z),this}clampScalar(e,t){return this.x=St(this.x,e,t),this.y=St(this.y,e,t),this.z=St(this.z,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(St(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this.z=e.z+(t.z-e.z)*i,this}cross(e){return this.crossVectors(this,e)}crossVectors(e,t){let i=e.x,s=e.y,r=e.z,o=t.x,a=t.y,l=t.z;return this.x=s*l-r*a,this.y=r*o-i*l,this.z=i*a-s*o,this}projectOnVector(e){let t=e.lengthSq();if(t===0)return this.set(0,0,0);let i=e.dot(this)/t;return this.copy(e).multiplyScalar(i)}projectOnPlane(e){return tf.copy(this).projectOnVector(e),this.sub(tf)}reflect(e){return this.sub(tf.copy(e).multiplyScalar(2*this.dot(e)))}angleTo(e){let t=Math.sqrt(this.lengthSq()*e.lengthSq());if(t===0)return Math.PI/2;let i=this.dot(e)/t;return Math.acos(St(i,-1,1))}distanceTo(e){return Math.sqrt(this.distanceToSquared(e))}distanceToSquared(e){let t=this.x-e.x,i=this.y-e.y,s=this.z-e.z;return t*t+i*i+s*s}manhattanDistanceTo(e){return Math.abs(this.x-e.x)+Math.abs(this.y-e.y)+Math.abs(this.z-e.z)}setFromSpherical(e){return this.setFromSphericalCoords(e.radius,e.phi,e.theta)}setFromSphericalCoords(e,t,i){let s=Math.sin(t)*e;return this.x=s*Math.sin(i),this.y=Math.cos(t)*e,this.z=s*Math.cos(i),this}setFromCylindrical(e){return this.setFromCylindricalCoords(e.radius,e.theta,e.y)}setFromCylindricalCoords(e,t,i){return this.x=e*Math.sin(t),this.y=i,this.z=e*Math.cos(t),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this}setFromMatrixScale(e){let t=this.setFromMatrixColumn(e,0).length(),i=this.setFromMatrixColumn(e,1).length(),s=this.setFromMatrixColumn(e,2).length();return this.x=t,this.y=i,this.z=s,this}setFromMatrixColumn(e,t){return this.fromArray(e.elements,t*4)}setFromMatrix3Column(e,t){return this.fromArray(e.elements,t*3)}setFromEuler(e){return this.x=e._x,this.y=e._y,this.z=e._z,this}setFromColor(e){return this.x=e.r,this.y=e.g,this.z=e.b,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this}randomDirection(){let e=Math.random()*Math.PI*2,t=Math.random()*2-1,i=Math.sqrt(1-t*t);return this.x=i*Math.cos(e),this.y=t,this.z=i*Math.sin(e),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z}};fd.prototype.isVector3=!0;var K=fd,tf=new K,gg=new di,dd=class dd{constructor(e,t,i,s,r,o,a,l,c){this.elements=[1,0,0,0,1,0,0,0,1],e!==void 0&&this.set(e,t,i,s,r,o,a,l,c)}set(e,t,i,s,r,o,a,l,c){let h=this.elements;return h[0]=e,h[1]=s,h[2]=a,h[3]=t,h[4]=r,h[5]=l,h[6]=i,h[7]=o,h[8]=c,this}identity(){return this.set(1,0,0,0,1,0,0,0,1),this}copy(e){let t=this.elements,i=e.elements;return t[0]=i[0],t[1]=i[1],t[2]=i[2],t[3]=i[3],t[4]=i[4],t[5]=i[5],t[6]=i[6],t[7]=i[7],t[8]=i[8],this}extractBasis(e,t,i){return e.setFromMatrix3Column(this,0),t.setFromMatrix3Column(this,1),i.setFromMatrix3Column(this,2),this}setFromMatrix4(e){let t=e.elements;return this.set(t[0],t[4],t[8],t[1],t[5],t[9],t[2],t[6],t[10]),this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let i=e.elements,s=t.elements,r=this.elements,o=i[0],a=i[3],l=i[6],c=i[1],h=i[4],f=i[7],u=i[2],p=i[5],g=i[8],S=s[0],d=s[3],m=s[6],y=s[1],A=s[4],b=s[7],C=s[2],E=s[5],x=s[8];return r[0]=o*S+a*y+l*C,r[3]=o*d+a*A+l*E,r[6]=o*m+a*b+l*x,r[1]=c*S+h*y+f*C,r[4]=c*d+h*A+f*E,r[7]=c*m+h*b+f*x,r[2]=u*S+p*y+g*C,r[5]=u*d+p*A+g*E,r[8]=u*m+p*b+g*x,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[3]*=e,t[6]*=e,t[1]*=e,t[4]*=e,t[7]*=e,t[2]*=e,t[5]*=e,t[8]*=e,this}determinant(){let e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],o=e[4],a=e[5],l=e[6],c=e[7],h=e[8];return t*o*h-t*a*c-i*r*h+i*a*l+s*r*c-s*o*l}invert(){let e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],o=e[4],a=e[5],l=e[6],c=e[7],h=e[8],f=h*o-a*c,u=a*l-h*r,p=c*r-o*l,g=t*f+i*u+s*p;if(g===0)return this.set(0,0,0,0,0,0,0,0,0);let S=1/g;return e[0]=f*S,e[1]=(s*c-h*i)*S,e[2]=(a*i-s*o)*S,e[3]=u*S,e[4]=(h*t-s*l)*S,e[5]=(s*r-a*t)*S,e[6]=p*S,e[7]=(i*l-c*t)*S,e[8]=(o*t-i*r)*S,this}transpose(){let e,t=this.elements;return e=t[1],t[1]=t[3],t[3]=e,e=t[2],t[2]=t[6],t[6]=e,e=t[5],t[5]=t[7],t[7]=e,this}getNormalMatrix(e){return this.setFromMatrix4(e).invert().transpose()}transposeIntoArray(e){let t=this.elements;return e[0]=t[0],e[1]=t[3],e[2]=t[6],e[3]=t[1],e[4]=t[4],e[5]=t[7],e[6]=t[2],e[7]=t[5],e[8]=t[8],this}setUvTransform(e,t,i,s,r,o,a){let l=Math.cos(r),c=Math.sin(r);return this.set(i*l,i*c,-i*(l*o+c*a)+o+e,-s*c,s*l,-s*(-c*o+l*a)+a+t,0,0,1),this}scale(e,t){return xa("Matrix3: .scale() is deprecated. Use .makeScale() instead."),this.premultiply(nf.makeScale(e,t)),this}rotate(e){return xa("Matrix3: .rotate() is deprecated. Use .makeRotation() instead."),this.premultiply(nf.makeRotation(-e)),this}translate(e,t){return xa("Matrix3: .translate() is deprecated. Use .makeTranslation() instead."),this.premultiply(nf.makeTranslation(e,t)),this}makeTranslation(e,t){return e.isVector2?this.set(1,0,e.x,0,1,e.y,0,0,1):this.set(1,0,e,0,1,t,0,0,1),this}makeRotation(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,-i,0,i,t,0,0,0,1),this}makeScale(e,t){return this.set(e,0,0,0,t,0,0,0,1),this}equals(e){let t=this.elements,i=e.elements;for(let s=0;s<9;s++)if(t[s]!==i[s])return!1;return!0}fromArray(e,t=0){for(let i=0;i<9;i++)this.elements[i]=e[i+t];return this}toArray(e=[],t=0){let i=this.elements;return e[t]=i[0],e[t+1]=i[1],e[t+2]=i[2],e[t+3]=i[3],e[t+4]=i[4],e[t+5]=i[5],e[t+6]=i[6],e[t+7]=i[7],e[t+8]=i[8],e}clone(){return new this.constructor().fromArray(this.elements)}};dd.prototype.isMatrix3=!0;var ot=dd,nf=new ot,_g=new ot().set(.4123908,.3575843,.1804808,.212639,.7151687,.0721923,.0193308,.1191948,.9505322),xg=new ot().set(3.2409699,-1.5373832,-.4986108,-.9692436,1.8759675,.0415551,.0556301,-.203977,1.0569715);function vv(){let n={enabled:!0,workingColorSpace:ba,spaces:{},convert:function(s,r,o){return this.enabled===!1||r===o||!r||!o||(this.spaces[r].transfer===Ft&&(s.r=vs(s.r),s.g=vs(s.g),s.b=vs(s.b)),this.spaces[r].primaries!==this.spaces[o].primaries&&(s.applyMatrix3(this.spaces[r].toXYZ),s.applyMatrix3(this.spaces[o].fromXYZ)),this.spaces[o].transfer===Ft&&(s.r=So(s.r),s.g=So(s.g),s.b=So(s.b))),s},workingToColorSpace:function(s,r){return this.convert(s,this.workingColorSpace,r)},colorSpaceToWorking:function(s,r){return this.convert(s,r,this.workingColorSpace)},getPrimaries:function(s){return this.spaces[s].primaries},getTransfer:function(s){return s===Ts?Ma:this.spaces[s].transfer},getToneMappingMode:function(s){return this.spaces[s].outputColorSpaceConfig.toneMappingMode||"standard"},getLuminanceCoefficients:function(s,r=this.workingColorSpace){return s.fromArray(this.spaces[r].luminanceCoefficients)},define:function(s){Object.assign(this.spaces,s)},_getMatrix:function(s,r,o){return s.copy(this.spaces[o].fromXYZ).multiply(this.spaces[r].toXYZ)},_getDrawingBufferColorSpace:function(s){return this.spaces[s].outputColorSpaceConfig.drawingBufferColorSpace},_getUnpackColorSpace:function(s=this.workingColorSpace){return this.spaces[s].workingColorSpaceConfig.unpackColorSpace}},e=[.64,.33,.3,.6,.15,.06],t=[.2126,.7152,.0722],i=[.3127,.329];return n.define({[ba]:{primaries:e,whitePoint:i,transfer:Ma,toXYZ:_g,fromXYZ:xg,luminanceCoefficients:t,workingColorSpaceConfig:{unpackColorSpace:hi},outputColorSpaceConfig:{drawingBufferColorSpace:hi}},[hi]:{primaries:e,whitePoint:i,transfer:Ft,toXYZ:_g,fromXYZ:xg,luminanceCoefficients:t,outputColorSpaceConfig:{drawingBufferColorSpace:hi}}}),n}var At=vv();function vs(n){return n<.04045?n*.0773993808:Math.pow(n*.9478672986+.0521327014,2.4)}function So(n){return n<.0031308?n*12.92:1.055*Math.pow(n,.41666)-.055}var ao,wc=class{static getDataURL(e,t="image/png"){if(/^data:/i.test(e.src)||typeof HTMLCanvasElement>"u")return e.src;let i;if(e instanceof HTMLCanvasElement)i=e;else{ao===void 0&&(ao=Ea("canvas")),ao.width=e.width,ao.height=e.height;let s=ao.getContext("2d");e instanceof ImageData?s.putImageData(e,0,0):s.drawImage(e,0,0,e.width,e.height),i=ao}return i.toDataURL(t)}static sRGBToLinear(e){if(typeof HTMLImageElement<"u"&&e instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&e instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&e instanceof ImageBitmap){let t=Ea("canvas");t.width=e.width,t.height=e.height;let i=t.getContext("2d");i.drawImage(e,0,0,e.width,e.height);let s=i.getImageData(0,0,e.width,e.height),r=s.data;for(let o=0;o<r.length;o++)r[o]=vs(r[o]/255)*255;return i.putImageData(s,0,0),t}else if(e.data){let t=e.data.slice(0);for(let i=0;i<t.length;i++)t instanceof Uint8Array||t instanceof Uint8ClampedArray?t[i]=Math.floor(vs(t[i]/255)*255):t[i]=vs(t[i]);return{data:t,width:e.width,height:e.height}}else return Je("ImageUtils.sRGBToLinear(): Unsupported image type. No color space conversion applied."),e}},Sv=0,Eo=class{constructor(e=null){this.isTextureSource=!0,Object.defineProperty(this,"id",{value:Sv++}),this.uuid=Oo(),this.data=e,this.dataReady=!0,this.version=0}getSize(e){let t=this.data;return typeof HTMLVideoElement<"u"&&t instanceof HTMLVideoElement?e.set(t.videoWidth,t.videoHeight,0):typeof VideoFrame<"u"&&t instanceof VideoFrame?e.set(t.displayWidth,t.displayHeight,0):t!==null?e.set(t.width||0,t.height||0,t.depth||0):e.set(0,0,0),e}set needsUpdate(e){e===!0&&this.version++}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.images[this.uuid]!==void 0)return e.images[this.uuid];let i={uuid:this.uuid,url:""},s=this.data;if(s!==null){let r;if(Array.isArray(s)){r=[];for(let o=0,a=s.length;o<a;o++)s[o].isDataTexture?r.push(sf(s[o].image)):r.push(sf(s[o]))}else r=sf(s);i.url=r}return t||(e.images[this.uuid]=i),i}};function sf(n){return typeof HTMLImageElement<"u"&&n instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&n instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&n instanceof ImageBitmap?wc.getDataURL(n):n.data?{data:Array.from(n.data),width:n.width,height:n.height,type:n.data.constructor.name}:(Je("Texture: Unable to serialize Texture."),{})}var bv=0,rf=new K,Kn=class n extends Di{constructor(e=n.DEFAULT_IMAGE,t=n.DEFAULT_MAPPING,i=Ji,s=Ji,r=Yn,o=ws,a=Bi,l=gi,c=n.DEFAULT_ANISOTROPY,h=Ts){super(),this.isTexture=!0,Object.defineProperty(this,"id",{value:bv++}),this.uuid=Oo(),this.name="",this.source=new Eo(e),this.mipmaps=[],this.mapping=t,this.channel=0,this.wrapS=i,this.wrapT=s,this.magFilter=r,this.minFilter=o,this.anisotropy=c,this.format=a,this.internalFormat=null,this.type=l,this.offset=new ut(0,0),this.repeat=new ut(1,1),this.center=new ut(0,0),this.rotation=0,this.matrixAutoUpdate=!0,this.matrix=new ot,this.generateMipmaps=!0,this.mipmapsAutoUpdate=!0,this.premultiplyAlpha=!1,this.flipY=!0,this.unpackAlignment=4,this.colorSpace=h,this.userData={},this.updateRanges=[],this.version=0,this.onUpdate=null,this.renderTarget=null,this.isRenderTargetTexture=!1,this.isArrayTexture=!!(e&&e.depth&&e.depth>1),this.pmremVersion=0,this.isPMREMTexture=!1,this.normalized=!1}get width(){return this.source.getSize(rf).x}get height(){return this.source.getSize(rf).y}get depth(){return this.source.getSize(rf).z}get image(){return this.source.data}set image(e){this.source.data=e}updateMatrix(){this.matrix.setUvTransform(this.offset.x,this.offset.y,this.repeat.x,this.repeat.y,this.rotation,this.center.x,this.center.y)}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}clone(){return new this.constructor().copy(this)}copy(e){return this.name=e.name,this.source=e.source,this.mipmaps=e.mipmaps.slice(0),this.mapping=e.mapping,this.channel=e.channel,this.wrapS=e.wrapS,this.wrapT=e.wrapT,this.magFilter=e.magFilter,this.minFilter=e.minFilter,this.anisotropy=e.anisotropy,this.format=e.format,this.internalFormat=e.internalFormat,this.type=e.type,this.normalized=e.normalized,this.offset.copy(e.offset),this.repeat.copy(e.repeat),this.center.copy(e.center),this.rotation=e.rotation,this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrix.copy(e.matrix),this.generateMipmaps=e.generateMipmaps,this.mipmapsAutoUpdate=e.mipmapsAutoUpdate,this.premultiplyAlpha=e.premultiplyAlpha,this.flipY=e.flipY,this.unpackAlignment=e.unpackAlignment,this.colorSpace=e.colorSpace,this.renderTarget=e.renderTarget,this.isRenderTargetTexture=e.isRenderTargetTexture,this.isPMREMTexture=e.isPMREMTexture,this.isArrayTexture=e.isArrayTexture,this.userData=JSON.parse(JSON.stringify(e.userData)),this.needsUpdate=!0,this}setValues(e){for(let t in e){let i=e[t];if(i===void 0){Je(`Texture.setValues(): parameter '${t}' has value of undefined.`);continue}let s=this[t];if(s===void 0){Je(`Texture.setValues(): property '${t}' does not exist.`);continue}s&&i&&s.isVector2&&i.isVector2||s&&i&&s.isVector3&&i.isVector3||s&&i&&s.isMatrix3&&i.isMatrix3?s.copy(i):this[t]=i}}toJSON(e){let t=e===void 0||typeof e=="string";if(!t&&e.textures[this.uuid]!==void 0)return e.textures[this.uuid];let i={metadata:{version:4.7,type:"Texture",generator:"Texture.toJSON"},uuid:this.uuid,name:this.name,image:this.source.toJSON(e).uuid,mapping:this.mapping,channel:this.channel,repeat:[this.repeat.x,this.repeat.y],offset:[this.offset.x,this.offset.y],center:[this.center.x,this.center.y],rotation:this.rotation,wrap:[this.wrapS,this.wrapT],format:this.format,internalFormat:this.internalFormat,type:this.type,normalized:this.normalized,colorSpace:this.colorSpace,minFilter:this.minFilter,magFilter:this.magFilter,anisotropy:this.anisotropy,flipY:this.flipY,generateMipmaps:this.generateMipmaps,mipmapsAutoUpdate:this.mipmapsAutoUpdate,premultiplyAlpha:this.premultiplyAlpha,unpackAlignment:this.unpackAlignment};return Object.keys(this.userData).length>0&&(i.userData=this.userData),t||(e.textures[this.uuid]=i),i}dispose(){this.dispatchEvent({type:"dispose"})}transformUv(e){if(this.mapping!==Vf)return e;if(e.applyMatrix3(this.matrix),e.x<0||e.x>1)switch(this.wrapS){case Sc:e.x=e.x-Math.floor(e.x);break;case Ji:e.x=e.x<0?0:1;break;case bc:Math.abs(Math.floor(e.x)%2)===1?e.x=Math.ceil(e.x)-e.x:e.x=e.x-Math.floor(e.x);break}if(e.y<0||e.y>1)switch(this.wrapT){case Sc:e.y=e.y-Math.floor(e.y);break;case Ji:e.y=e.y<0?0:1;break;case bc:Math.abs(Math.floor(e.y)%2)===1?e.y=Math.ceil(e.y)-e.y:e.y=e.y-Math.floor(e.y);break}return this.flipY&&(e.y=1-e.y),e}set needsUpdate(e){e===!0&&(this.version++,this.source.needsUpdate=!0)}set needsPMREMUpdate(e){e===!0&&this.pmremVersion++}};Kn.DEFAULT_IMAGE=null;Kn.DEFAULT_MAPPING=Vf;Kn.DEFAULT_ANISOTROPY=1;var pd=class pd{constructor(e=0,t=0,i=0,s=1){this.x=e,this.y=t,this.z=i,this.w=s}get width(){return this.z}set width(e){this.z=e}get height(){return this.w}set height(e){this.w=e}set(e,t,i,s){return this.x=e,this.y=t,this.z=i,this.w=s,this}setScalar(e){return this.x=e,this.y=e,this.z=e,this.w=e,this}setX(e){return this.x=e,this}setY(e){return this.y=e,this}setZ(e){return this.z=e,this}setW(e){return this.w=e,this}setComponent(e,t){switch(e){case 0:this.x=t;break;case 1:this.y=t;break;case 2:this.z=t;break;case 3:this.w=t;break;default:throw new Error("THREE.Vector4: index is out of range: "+e)}return this}getComponent(e){switch(e){case 0:return this.x;case 1:return this.y;case 2:return this.z;case 3:return this.w;default:throw new Error("THREE.Vector4: index is out of range: "+e)}}clone(){return new this.constructor(this.x,this.y,this.z,this.w)}copy(e){return this.x=e.x,this.y=e.y,this.z=e.z,this.w=e.w!==void 0?e.w:1,this}add(e){return this.x+=e.x,this.y+=e.y,this.z+=e.z,this.w+=e.w,this}addScalar(e){return this.x+=e,this.y+=e,this.z+=e,this.w+=e,this}addVectors(e,t){return this.x=e.x+t.x,this.y=e.y+t.y,this.z=e.z+t.z,this.w=e.w+t.w,this}addScaledVector(e,t){return this.x+=e.x*t,this.y+=e.y*t,this.z+=e.z*t,this.w+=e.w*t,this}sub(e){return this.x-=e.x,this.y-=e.y,this.z-=e.z,this.w-=e.w,this}subScalar(e){return this.x-=e,this.y-=e,this.z-=e,this.w-=e,this}subVectors(e,t){return this.x=e.x-t.x,this.y=e.y-t.y,this.z=e.z-t.z,this.w=e.w-t.w,this}multiply(e){return this.x*=e.x,this.y*=e.y,this.z*=e.z,this.w*=e.w,this}multiplyScalar(e){return this.x*=e,this.y*=e,this.z*=e,this.w*=e,this}applyMatrix4(e){let t=this.x,i=this.y,s=this.z,r=this.w,o=e.elements;return this.x=o[0]*t+o[4]*i+o[8]*s+o[12]*r,this.y=o[1]*t+o[5]*i+o[9]*s+o[13]*r,this.z=o[2]*t+o[6]*i+o[10]*s+o[14]*r,this.w=o[3]*t+o[7]*i+o[11]*s+o[15]*r,this}divide(e){return this.x/=e.x,this.y/=e.y,this.z/=e.z,this.w/=e.w,this}divideScalar(e){return this.multiplyScalar(1/e)}setAxisAngleFromQuaternion(e){this.w=2*Math.acos(e.w);let t=Math.sqrt(1-e.w*e.w);return t<1e-4?(this.x=1,this.y=0,this.z=0):(this.x=e.x/t,this.y=e.y/t,this.z=e.z/t),this}setAxisAngleFromRotationMatrix(e){let t,i,s,r,l=e.elements,c=l[0],h=l[4],f=l[8],u=l[1],p=l[5],g=l[9],S=l[2],d=l[6],m=l[10];if(Math.abs(h-u)<.01&&Math.abs(f-S)<.01&&Math.abs(g-d)<.01){if(Math.abs(h+u)<.1&&Math.abs(f+S)<.1&&Math.abs(g+d)<.1&&Math.abs(c+p+m-3)<.1)return this.set(1,0,0,0),this;t=Math.PI;let A=(c+1)/2,b=(p+1)/2,C=(m+1)/2,E=(h+u)/4,x=(f+S)/4,T=(g+d)/4;return A>b&&A>C?A<.01?(i=0,s=.707106781,r=.707106781):(i=Math.sqrt(A),s=E/i,r=x/i):b>C?b<.01?(i=.707106781,s=0,r=.707106781):(s=Math.sqrt(b),i=E/s,r=T/s):C<.01?(i=.707106781,s=.707106781,r=0):(r=Math.sqrt(C),i=x/r,s=T/r),this.set(i,s,r,t),this}let y=Math.sqrt((d-g)*(d-g)+(f-S)*(f-S)+(u-h)*(u-h));return Math.abs(y)<.001&&(y=1),this.x=(d-g)/y,this.y=(f-S)/y,this.z=(u-h)/y,this.w=Math.acos((c+p+m-1)/2),this}setFromMatrixPosition(e){let t=e.elements;return this.x=t[12],this.y=t[13],this.z=t[14],this.w=t[15],this}min(e){return this.x=Math.min(this.x,e.x),this.y=Math.min(this.y,e.y),this.z=Math.min(this.z,e.z),this.w=Math.min(this.w,e.w),this}max(e){return this.x=Math.max(this.x,e.x),this.y=Math.max(this.y,e.y),this.z=Math.max(this.z,e.z),this.w=Math.max(this.w,e.w),this}clamp(e,t){return this.x=St(this.x,e.x,t.x),this.y=St(this.y,e.y,t.y),this.z=St(this.z,e.z,t.z),this.w=St(this.w,e.w,t.w),this}clampScalar(e,t){return this.x=St(this.x,e,t),this.y=St(this.y,e,t),this.z=St(this.z,e,t),this.w=St(this.w,e,t),this}clampLength(e,t){let i=this.length();return this.divideScalar(i||1).multiplyScalar(St(i,e,t))}floor(){return this.x=Math.floor(this.x),this.y=Math.floor(this.y),this.z=Math.floor(this.z),this.w=Math.floor(this.w),this}ceil(){return this.x=Math.ceil(this.x),this.y=Math.ceil(this.y),this.z=Math.ceil(this.z),this.w=Math.ceil(this.w),this}round(){return this.x=Math.round(this.x),this.y=Math.round(this.y),this.z=Math.round(this.z),this.w=Math.round(this.w),this}roundToZero(){return this.x=Math.trunc(this.x),this.y=Math.trunc(this.y),this.z=Math.trunc(this.z),this.w=Math.trunc(this.w),this}negate(){return this.x=-this.x,this.y=-this.y,this.z=-this.z,this.w=-this.w,this}dot(e){return this.x*e.x+this.y*e.y+this.z*e.z+this.w*e.w}lengthSq(){return this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w}length(){return Math.sqrt(this.x*this.x+this.y*this.y+this.z*this.z+this.w*this.w)}manhattanLength(){return Math.abs(this.x)+Math.abs(this.y)+Math.abs(this.z)+Math.abs(this.w)}normalize(){return this.divideScalar(this.length()||1)}setLength(e){return this.normalize().multiplyScalar(e)}lerp(e,t){return this.x+=(e.x-this.x)*t,this.y+=(e.y-this.y)*t,this.z+=(e.z-this.z)*t,this.w+=(e.w-this.w)*t,this}lerpVectors(e,t,i){return this.x=e.x+(t.x-e.x)*i,this.y=e.y+(t.y-e.y)*i,this.z=e.z+(t.z-e.z)*i,this.w=e.w+(t.w-e.w)*i,this}equals(e){return e.x===this.x&&e.y===this.y&&e.z===this.z&&e.w===this.w}fromArray(e,t=0){return this.x=e[t],this.y=e[t+1],this.z=e[t+2],this.w=e[t+3],this}toArray(e=[],t=0){return e[t]=this.x,e[t+1]=this.y,e[t+2]=this.z,e[t+3]=this.w,e}fromBufferAttribute(e,t){return this.x=e.getX(t),this.y=e.getY(t),this.z=e.getZ(t),this.w=e.getW(t),this}random(){return this.x=Math.random(),this.y=Math.random(),this.z=Math.random(),this.w=Math.random(),this}*[Symbol.iterator](){yield this.x,yield this.y,yield this.z,yield this.w}};pd.prototype.isVector4=!0;var sn=pd,Ec=class extends Di{constructor(e=1,t=1,i={}){super(),i=Object.assign({generateMipmaps:!1,internalFormat:null,minFilter:Yn,depthBuffer:!0,stencilBuffer:!1,resolveColorBuffer:!0,resolveDepthBuffer:!0,resolveStencilBuffer:!0,storeMultisampledColorBuffer:!0,storeMultisampledDepthBuffer:!0,storeMultisampledStencilBuffer:!0,depthTexture:null,samples:0,count:1,depth:1,multiview:!1,useArrayDepthTexture:!1},i),this.isRenderTarget=!0,this.width=e,this.height=t,this.depth=i.depth,this.scissor=new sn(0,0,e,t),this.scissorTest=!1,this.viewport=new sn(0,0,e,t),this.textures=[];let s=i.count;for(let r=0;r<s;r++)this.textures[r]=new Kn({width:e,height:t,depth:i.depth}),this.textures[r].isRenderTargetTexture=!0,this.textures[r].renderTarget=this;this._setTextureOptions(i),this.depthBuffer=i.depthBuffer,this.stencilBuffer=i.stencilBuffer,this.resolveColorBuffer=i.resolveColorBuffer,this.resolveDepthBuffer=i.resolveDepthBuffer,this.resolveStencilBuffer=i.resolveStencilBuffer,this.storeMultisampledColorBuffer=i.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=i.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=i.storeMultisampledStencilBuffer,this._depthTexture=null,this.depthTexture=i.depthTexture,this.samples=i.samples,this.multiview=i.multiview,this.useArrayDepthTexture=i.useArrayDepthTexture}_setTextureOptions(e={}){let t={minFilter:Yn,generateMipmaps:!1,flipY:!1,internalFormat:null};e.mapping!==void 0&&(t.mapping=e.mapping),e.wrapS!==void 0&&(t.wrapS=e.wrapS),e.wrapT!==void 0&&(t.wrapT=e.wrapT),e.wrapR!==void 0&&(t.wrapR=e.wrapR),e.magFilter!==void 0&&(t.magFilter=e.magFilter),e.minFilter!==void 0&&(t.minFilter=e.minFilter),e.format!==void 0&&(t.format=e.format),e.type!==void 0&&(t.type=e.type),e.anisotropy!==void 0&&(t.anisotropy=e.anisotropy),e.colorSpace!==void 0&&(t.colorSpace=e.colorSpace),e.flipY!==void 0&&(t.flipY=e.flipY),e.generateMipmaps!==void 0&&(t.generateMipmaps=e.generateMipmaps),e.mipmapsAutoUpdate!==void 0&&(t.mipmapsAutoUpdate=e.mipmapsAutoUpdate),e.internalFormat!==void 0&&(t.internalFormat=e.internalFormat);for(let i=0;i<this.textures.length;i++)this.textures[i].setValues(t)}get texture(){return this.textures[0]}set texture(e){this.textures[0]=e}set depthTexture(e){this._depthTexture!==null&&this._depthTexture.renderTarget===this&&(this._depthTexture.renderTarget=null),e!==null&&e.renderTarget===null&&(e.renderTarget=this),this._depthTexture=e}get depthTexture(){return this._depthTexture}setSize(e,t,i=1){if(this.width!==e||this.height!==t||this.depth!==i){this.width=e,this.height=t,this.depth=i;for(let s=0,r=this.textures.length;s<r;s++)this.textures[s].image.width=e,this.textures[s].image.height=t,this.textures[s].image.depth=i,this.textures[s].isData3DTexture!==!0&&(this.textures[s].isArrayTexture=this.textures[s].image.depth>1);this.dispose()}this.viewport.set(0,0,e,t),this.scissor.set(0,0,e,t)}clone(){return new this.constructor().copy(this)}copy(e){this.width=e.width,this.height=e.height,this.depth=e.depth,this.scissor.copy(e.scissor),this.scissorTest=e.scissorTest,this.viewport.copy(e.viewport),this.textures.length=0;for(let t=0,i=e.textures.length;t<i;t++){this.textures[t]=e.textures[t].clone(),this.textures[t].isRenderTargetTexture=!0,this.textures[t].renderTarget=this;let s=Object.assign({},e.textures[t].image);this.textures[t].source=new Eo(s)}if(this.depthBuffer=e.depthBuffer,this.stencilBuffer=e.stencilBuffer,this.resolveColorBuffer=e.resolveColorBuffer,this.resolveDepthBuffer=e.resolveDepthBuffer,this.resolveStencilBuffer=e.resolveStencilBuffer,this.storeMultisampledColorBuffer=e.storeMultisampledColorBuffer,this.storeMultisampledDepthBuffer=e.storeMultisampledDepthBuffer,this.storeMultisampledStencilBuffer=e.storeMultisampledStencilBuffer,e.depthTexture!==null)if(e.depthTexture.renderTarget===e){let t=e.depthTexture.clone();t.renderTarget=null,this.depthTexture=t}else this.depthTexture=e.depthTexture;else this.depthTexture=null;return this.samples=e.samples,this.multiview=e.multiview,this.useArrayDepthTexture=e.useArrayDepthTexture,this}dispose(){this.dispatchEvent({type:"dispose"})}},pi=class extends Ec{constructor(e=1,t=1,i={}){super(e,t,i),this.isWebGLRenderTarget=!0}},Ta=class extends Kn{constructor(e=null,t=1,i=1,s=1){super(null),this.isDataArrayTexture=!0,this.image={data:e,width:t,height:i,depth:s},this.magFilter=Ln,this.minFilter=Ln,this.wrapR=Ji,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1,this.layerUpdates=new Set}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}addLayerUpdate(e){this.layerUpdates.add(e)}clearLayerUpdates(){this.layerUpdates.clear()}};var Tc=class extends Kn{constructor(e=null,t=1,i=1,s=1){super(null),this.isData3DTexture=!0,this.image={data:e,width:t,height:i,depth:s},this.magFilter=Ln,this.minFilter=Ln,this.wrapR=Ji,this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}copy(e){return super.copy(e),this.wrapR=e.wrapR,this}};var $c=class $c{constructor(e,t,i,s,r,o,a,l,c,h,f,u,p,g,S,d){this.elements=[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],e!==void 0&&this.set(e,t,i,s,r,o,a,l,c,h,f,u,p,g,S,d)}set(e,t,i,s,r,o,a,l,c,h,f,u,p,g,S,d){let m=this.elements;return m[0]=e,m[4]=t,m[8]=i,m[12]=s,m[1]=r,m[5]=o,m[9]=a,m[13]=l,m[2]=c,m[6]=h,m[10]=f,m[14]=u,m[3]=p,m[7]=g,m[11]=S,m[15]=d,this}identity(){return this.set(1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1),this}clone(){return new $c().fromArray(this.elements)}copy(e){let t=this.elements,i=e.elements;return t[0]=i[0],t[1]=i[1],t[2]=i[2],t[3]=i[3],t[4]=i[4],t[5]=i[5],t[6]=i[6],t[7]=i[7],t[8]=i[8],t[9]=i[9],t[10]=i[10],t[11]=i[11],t[12]=i[12],t[13]=i[13],t[14]=i[14],t[15]=i[15],this}copyPosition(e){let t=this.elements,i=e.elements;return t[12]=i[12],t[13]=i[13],t[14]=i[14],this}setFromMatrix3(e){let t=e.elements;return this.set(t[0],t[3],t[6],0,t[1],t[4],t[7],0,t[2],t[5],t[8],0,0,0,0,1),this}extractBasis(e,t,i){return this.determinantAffine()===0?(e.set(1,0,0),t.set(0,1,0),i.set(0,0,1),this):(e.setFromMatrixColumn(this,0),t.setFromMatrixColumn(this,1),i.setFromMatrixColumn(this,2),this)}makeBasis(e,t,i){return this.set(e.x,t.x,i.x,0,e.y,t.y,i.y,0,e.z,t.z,i.z,0,0,0,0,1),this}extractRotation(e){if(e.determinantAffine()===0)return this.identity();let t=this.elements,i=e.elements,s=1/lo.setFromMatrixColumn(e,0).length(),r=1/lo.setFromMatrixColumn(e,1).length(),o=1/lo.setFromMatrixColumn(e,2).length();return t[0]=i[0]*s,t[1]=i[1]*s,t[2]=i[2]*s,t[3]=0,t[4]=i[4]*r,t[5]=i[5]*r,t[6]=i[6]*r,t[7]=0,t[8]=i[8]*o,t[9]=i[9]*o,t[10]=i[10]*o,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromEuler(e){let t=this.elements,i=e.x,s=e.y,r=e.z,o=Math.cos(i),a=Math.sin(i),l=Math.cos(s),c=Math.sin(s),h=Math.cos(r),f=Math.sin(r);if(e.order==="XYZ"){let u=o*h,p=o*f,g=a*h,S=a*f;t[0]=l*h,t[4]=-l*f,t[8]=c,t[1]=p+g*c,t[5]=u-S*c,t[9]=-a*l,t[2]=S-u*c,t[6]=g+p*c,t[10]=o*l}else if(e.order==="YXZ"){let u=l*h,p=l*f,g=c*h,S=c*f;t[0]=u+S*a,t[4]=g*a-p,t[8]=o*c,t[1]=o*f,t[5]=o*h,t[9]=-a,t[2]=p*a-g,t[6]=S+u*a,t[10]=o*l}else if(e.order==="ZXY"){let u=l*h,p=l*f,g=c*h,S=c*f;t[0]=u-S*a,t[4]=-o*f,t[8]=g+p*a,t[1]=p+g*a,t[5]=o*h,t[9]=S-u*a,t[2]=-o*c,t[6]=a,t[10]=o*l}else if(e.order==="ZYX"){let u=o*h,p=o*f,g=a*h,S=a*f;t[0]=l*h,t[4]=g*c-p,t[8]=u*c+S,t[1]=l*f,t[5]=S*c+u,t[9]=p*c-g,t[2]=-c,t[6]=a*l,t[10]=o*l}else if(e.order==="YZX"){let u=o*l,p=o*c,g=a*l,S=a*c;t[0]=l*h,t[4]=S-u*f,t[8]=g*f+p,t[1]=f,t[5]=o*h,t[9]=-a*h,t[2]=-c*h,t[6]=p*f+g,t[10]=u-S*f}else if(e.order==="XZY"){let u=o*l,p=o*c,g=a*l,S=a*c;t[0]=l*h,t[4]=-f,t[8]=c*h,t[1]=u*f+S,t[5]=o*h,t[9]=p*f-g,t[2]=g*f-p,t[6]=a*h,t[10]=S*f+u}return t[3]=0,t[7]=0,t[11]=0,t[12]=0,t[13]=0,t[14]=0,t[15]=1,this}makeRotationFromQuaternion(e){return this.compose(Mv,e,wv)}lookAt(e,t,i){let s=this.elements;return li.subVectors(e,t),li.lengthSq()===0&&(li.z=1),li.normalize(),Ws.crossVectors(i,li),Ws.lengthSq()===0&&(Math.abs(i.z)===1?li.x+=1e-4:li.z+=1e-4,li.normalize(),Ws.crossVectors(i,li)),Ws.normalize(),Hl.crossVectors(li,Ws),s[0]=Ws.x,s[4]=Hl.x,s[8]=li.x,s[1]=Ws.y,s[5]=Hl.y,s[9]=li.y,s[2]=Ws.z,s[6]=Hl.z,s[10]=li.z,this}multiply(e){return this.multiplyMatrices(this,e)}premultiply(e){return this.multiplyMatrices(e,this)}multiplyMatrices(e,t){let i=e.elements,s=t.elements,r=this.elements,o=i[0],a=i[4],l=i[8],c=i[12],h=i[1],f=i[5],u=i[9],p=i[13],g=i[2],S=i[6],d=i[10],m=i[14],y=i[3],A=i[7],b=i[11],C=i[15],E=s[0],x=s[4],T=s[8],k=s[12],U=s[1],P=s[5],B=s[9],z=s[13],L=s[2],H=s[6],W=s[10],D=s[14],te=s[3],X=s[7],q=s[11],j=s[15];return r[0]=o*E+a*U+l*L+c*te,r[4]=o*x+a*P+l*H+c*X,r[8]=o*T+a*B+l*W+c*q,r[12]=o*k+a*z+l*D+c*j,r[1]=h*E+f*U+u*L+p*te,r[5]=h*x+f*P+u*H+p*X,r[9]=h*T+f*B+u*W+p*q,r[13]=h*k+f*z+u*D+p*j,r[2]=g*E+S*U+d*L+m*te,r[6]=g*x+S*P+d*H+m*X,r[10]=g*T+S*B+d*W+m*q,r[14]=g*k+S*z+d*D+m*j,r[3]=y*E+A*U+b*L+C*te,r[7]=y*x+A*P+b*H+C*X,r[11]=y*T+A*B+b*W+C*q,r[15]=y*k+A*z+b*D+C*j,this}multiplyScalar(e){let t=this.elements;return t[0]*=e,t[4]*=e,t[8]*=e,t[12]*=e,t[1]*=e,t[5]*=e,t[9]*=e,t[13]*=e,t[2]*=e,t[6]*=e,t[10]*=e,t[14]*=e,t[3]*=e,t[7]*=e,t[11]*=e,t[15]*=e,this}determinant(){let e=this.elements,t=e[0],i=e[4],s=e[8],r=e[12],o=e[1],a=e[5],l=e[9],c=e[13],h=e[2],f=e[6],u=e[10],p=e[14],g=e[3],S=e[7],d=e[11],m=e[15],y=l*p-c*u,A=a*p-c*f,b=a*u-l*f,C=o*p-c*h,E=o*u-l*h,x=o*f-a*h;return t*(S*y-d*A+m*b)-i*(g*y-d*C+m*E)+s*(g*A-S*C+m*x)-r*(g*b-S*E+d*x)}determinantAffine(){let e=this.elements,t=e[0],i=e[4],s=e[8],r=e[1],o=e[5],a=e[9],l=e[2],c=e[6],h=e[10];return t*(o*h-a*c)-i*(r*h-a*l)+s*(r*c-o*l)}transpose(){let e=this.elements,t;return t=e[1],e[1]=e[4],e[4]=t,t=e[2],e[2]=e[8],e[8]=t,t=e[6],e[6]=e[9],e[9]=t,t=e[3],e[3]=e[12],e[12]=t,t=e[7],e[7]=e[13],e[13]=t,t=e[11],e[11]=e[14],e[14]=t,this}setPosition(e,t,i){let s=this.elements;return e.isVector3?(s[12]=e.x,s[13]=e.y,s[14]=e.z):(s[12]=e,s[13]=t,s[14]=i),this}invert(){let e=this.elements,t=e[0],i=e[1],s=e[2],r=e[3],o=e[4],a=e[5],l=e[6],c=e[7],h=e[8],f=e[9],u=e[10],p=e[11],g=e[12],S=e[13],d=e[14],m=e[15],y=t*a-i*o,A=t*l-s*o,b=t*c-r*o,C=i*l-s*a,E=i*c-r*a,x=s*c-r*l,T=h*S-f*g,k=h*d-u*g,U=h*m-p*g,P=f*d-u*S,B=f*m-p*S,z=u*m-p*d,L=y*z-A*B+b*P+C*U-E*k+x*T;if(L===0)return this.set(0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0);let H=1/L;return e[0]=(a*z-l*B+c*P)*H,e[1]=(s*B-i*z-r*P)*H,e[2]=(S*x-d*E+m*C)*H,e[3]=(u*E-f*x-p*C)*H,e[4]=(l*U-o*z-c*k)*H,e[5]=(t*z-s*U+r*k)*H,e[6]=(d*b-g*x-m*A)*H,e[7]=(h*x-u*b+p*A)*H,e[8]=(o*B-a*U+c*T)*H,e[9]=(i*U-t*B-r*T)*H,e[10]=(g*E-S*b+m*y)*H,e[11]=(f*b-h*E-p*y)*H,e[12]=(a*k-o*P-l*T)*H,e[13]=(t*P-i*k+s*T)*H,e[14]=(S*A-g*C-d*y)*H,e[15]=(h*C-f*A+u*y)*H,this}scale(e){let t=this.elements,i=e.x,s=e.y,r=e.z;return t[0]*=i,t[4]*=s,t[8]*=r,t[1]*=i,t[5]*=s,t[9]*=r,t[2]*=i,t[6]*=s,t[10]*=r,t[3]*=i,t[7]*=s,t[11]*=r,this}getMaxScaleOnAxis(){let e=this.elements,t=e[0]*e[0]+e[1]*e[1]+e[2]*e[2],i=e[4]*e[4]+e[5]*e[5]+e[6]*e[6],s=e[8]*e[8]+e[9]*e[9]+e[10]*e[10];return Math.sqrt(Math.max(t,i,s))}makeTranslation(e,t,i){return e.isVector3?this.set(1,0,0,e.x,0,1,0,e.y,0,0,1,e.z,0,0,0,1):this.set(1,0,0,e,0,1,0,t,0,0,1,i,0,0,0,1),this}makeRotationX(e){let t=Math.cos(e),i=Math.sin(e);return this.set(1,0,0,0,0,t,-i,0,0,i,t,0,0,0,0,1),this}makeRotationY(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,0,i,0,0,1,0,0,-i,0,t,0,0,0,0,1),this}makeRotationZ(e){let t=Math.cos(e),i=Math.sin(e);return this.set(t,-i,0,0,i,t,0,0,0,0,1,0,0,0,0,1),this}makeRotationAxis(e,t){let i=Math.cos(t),s=Math.sin(t),r=1-i,o=e.x,a=e.y,l=e.z,c=r*o,h=r*a;return this.set(c*o+i,c*a-s*l,c*l+s*a,0,c*a+s*l,h*a+i,h*l-s*o,0,c*l-s*a,h*l+s*o,r*l*l+i,0,0,0,0,1),this}makeScale(e,t,i){return this.set(e,0,0,0,0,t,0,0,0,0,i,0,0,0,0,1),this}makeShear(e,t,i,s,r,o){return this.set(1,i,r,0,e,1,o,0,t,s,1,0,0,0,0,1),this}compose(e,t,i){let s=this.elements,r=t._x,o=t._y,a=t._z,l=t._w,c=r+r,h=o+o,f=a+a,u=r*c,p=r*h,g=r*f,S=o*h,d=o*f,m=a*f,y=l*c,A=l*h,b=l*f,C=i.x,E=i.y,x=i.z;return s[0]=(1-(S+m))*C,s[1]=(p+b)*C,s[2]=(g-A)*C,s[3]=0,s[4]=(p-b)*E,s[5]=(1-(u+m))*E,s[6]=(d+y)*E,s[7]=0,s[8]=(g+A)*x,s[9]=(d-y)*x,s[10]=(1-(u+S))*x,s[11]=0,s[12]=e.x,s[13]=e.y,s[14]=e.z,s[15]=1,this}decompose(e,t,i){let s=this.elements;e.x=s[12],e.y=s[13],e.z=s[14];let r=this.determinantAffine();if(r===0)return i.set(1,1,1),t.identity(),this;let o=lo.set(s[0],s[1],s[2]).length(),a=lo.set(s[4],s[5],s[6]).length(),l=lo.set(s[8],s[9],s[10]).length();r<0&&(o=-o),Pi.copy(this);let c=1/o,h=1/a,f=1/l;return Pi.elements[0]*=c,Pi.elements[1]*=c,Pi.elements[2]*=c,Pi.elements[4]*=h,Pi.elements[5]*=h,Pi.elements[6]*=h,Pi.elements[8]*=f,Pi.elements[9]*=f,Pi.elements[10]*=f,t.setFromRotationMatrix(Pi),i.x=o,i.y=a,i.z=l,this}makePerspective(e,t,i,s,r,o,a=Mi,l=!1){let c=this.elements,h=2*r/(t-e),f=2*r/(i-s),u=(t+e)/(t-e),p=(i+s)/(i-s),g,S;if(l)g=r/(o-r),S=o*r/(o-r);else if(a===Mi)g=-(o+r)/(o-r),S=-2*o*r/(o-r);else if(a===wa)g=-o/(o-r),S=-o*r/(o-r);else throw new Error("THREE.Matrix4.makePerspective(): Invalid coordinate system: "+a);return c[0]=h,c[4]=0,c[8]=u,c[12]=0,c[1]=0,c[5]=f,c[9]=p,c[13]=0,c[2]=0,c[6]=0,c[10]=g,c[14]=S,c[3]=0,c[7]=0,c[11]=-1,c[15]=0,this}makeOrthographic(e,t,i,s,r,o,a=Mi,l=!1){let c=this.elements,h=2/(t-e),f=2/(i-s),u=-(t+e)/(t-e),p=-(i+s)/(i-s),g,S;if(l)g=1/(o-r),S=o/(o-r);else if(a===Mi)g=-2/(o-r),S=-(o+r)/(o-r);else if(a===wa)g=-1/(o-r),S=-r/(o-r);else throw new Error("THREE.Matrix4.makeOrthographic(): Invalid coordinate system: "+a);return c[0]=h,c[4]=0,c[8]=0,c[12]=u,c[1]=0,c[5]=f,c[9]=0,c[13]=p,c[2]=0,c[6]=0,c[10]=g,c[14]=S,c[3]=0,c[7]=0,c[11]=0,c[15]=1,this}equals(e){let t=this.elements,i=e.elements;for(let s=0;s<16;s++)if(t[s]!==i[s])return!1;return!0}fromArray(e,t=0){for(let i=0;i<16;i++)this.elements[i]=e[i+t];return this}toArray(e=[],t=0){let i=this.elements;return e[t]=i[0],e[t+1]=i[1],e[t+2]=i[2],e[t+3]=i[3],e[t+4]=i[4],e[t+5]=i[5],e[t+6]=i[6],e[t+7]=i[7],e[t+8]=i[8],e[t+9]=i[9],e[t+10]=i[10],e[t+11]=i[11],e[t+12]=i[12],e[t+13]=i[13],e[t+14]=i[14],e[t+15]=i[15],e}};$c.prototype.isMatrix4=!0;var en=$c,lo=new K,Pi=new en,Mv=new K(0,0,0),wv=new K(1,1,1),Ws=new K,Hl=new K,li=new K,yg=new en,vg=new di,Ks=class n{constructor(e=0,t=0,i=0,s=n.DEFAULT_ORDER){this.isEuler=!0,this._x=e,this._y=t,this._z=i,this._order=s}get x(){return this._x}set x(e){this._x=e,this._onChangeCallback()}get y(){return this._y}set y(e){this._y=e,this._onChangeCallback()}get z(){return this._z}set z(e){this._z=e,this._onChangeCallback()}get order(){return this._order}set order(e){this._order=e,this._onChangeCallback()}set(e,t,i,s=this._order){return this._x=e,this._y=t,this._z=i,this._order=s,this._onChangeCallback(),this}clone(){return new this.constructor(this._x,this._y,this._z,this._order)}copy(e){return this._x=e._x,this._y=e._y,this._z=e._z,this._order=e._order,this._onChangeCallback(),this}setFromRotationMatrix(e,t=this._order,i=!0){let s=e.elements,r=s[0],o=s[4],a=s[8],l=s[1],c=s[5],h=s[9],f=s[2],u=s[6],p=s[10];switch(t){case"XYZ":this._y=Math.asin(St(a,-1,1)),Math.abs(a)<.9999999?(this._x=Math.atan2(-h,p),this._z=Math.atan2(-o,r)):(this._x=Math.atan2(u,c),this._z=0);break;case"YXZ":this._x=Math.asin(-St(h,-1,1)),Math.abs(h)<.9999999?(this._y=Math.atan2(a,p),this._z=Math.atan2(l,c)):(this._y=Math.atan2(-f,r),this._z=0);break;case"ZXY":this._x=Math.asin(St(u,-1,1)),Math.abs(u)<.9999999?(this._y=Math.atan2(-f,p),this._z=Math.atan2(-o,c)):(this._y=0,this._z=Math.atan2(l,r));break;case"ZYX":this._y=Math.asin(-St(f,-1,1)),Math.abs(f)<.9999999?(this._x=Math.atan2(u,p),this._z=Math.atan2(l,r)):(this._x=0,this._z=Math.atan2(-o,c));break;case"YZX":this._z=Math.asin(St(l,-1,1)),Math.abs(l)<.9999999?(this._x=Math.atan2(-h,c),this._y=Math.atan2(-f,r)):(this._x=0,this._y=Math.atan2(a,p));break;case"XZY":this._z=Math.asin(-St(o,-1,1)),Math.abs(o)<.9999999?(this._x=Math.atan2(u,c),this._y=Math.atan2(a,r)):(this._x=Math.atan2(-h,p),this._y=0);break;default:Je("Euler: .setFromRotationMatrix() encountered an unknown order: "+t)}return this._order=t,i===!0&&this._onChangeCallback(),this}setFromQuaternion(e,t,i){return yg.makeRotationFromQuaternion(e),this.setFromRotationMatrix(yg,t,i)}setFromVector3(e,t=this._order){return this.set(e.x,e.y,e.z,t)}reorder(e){return vg.setFromEuler(this),this.setFromQuaternion(vg,e)}equals(e){return e._x===this._x&&e._y===this._y&&e._z===this._z&&e._order===this._order}fromArray(e){return this._x=e[0],this._y=e[1],this._z=e[2],e[3]!==void 0&&(this._order=e[3]),this._onChangeCallback(),this}toArray(e=[],t=0){return e[t]=this._x,e[t+1]=this._y,e[t+2]=this._z,e[t+3]=this._order,e}_onChange(e){return this._onChangeCallback=e,this}_onChangeCallback(){}*[Symbol.iterator](){yield this._x,yield this._y,yield this._z,yield this._order}};Ks.DEFAULT_ORDER="XYZ";var Aa=class{constructor(){this.mask=1}set(e){this.mask=(1<<e|0)>>>0}enable(e){this.mask|=1<<e|0}enableAll(){this.mask=-1}toggle(e){this.mask^=1<<e|0}disable(e){this.mask&=~(1<<e|0)}disableAll(){this.mask=0}test(e){return(this.mask&e.mask)!==0}isEnabled(e){return(this.mask&(1<<e|0))!==0}},Ev=0,Sg=new K,co=new di,ms=new en,Vl=new K,da=new K,Tv=new K,Av=new di,bg=new K(1,0,0),Mg=new K(0,1,0),wg=new K(0,0,1),Eg={type:"added"},Rv={type:"removed"},ho={type:"childadded",child:null},of={type:"childremoved",child:null},Jn=class n extends Di{constructor(){super(),this.isObject3D=!0,Object.defineProperty(this,"id",{value:Ev++}),this.uuid=Oo(),this.name="",this.type="Object3D",this.parent=null,this.children=[],this.up=n.DEFAULT_UP.clone();let e=new K,t=new Ks,i=new di,s=new K(1,1,1);function r(){i.setFromEuler(t,!1)}function o(){t.setFromQuaternion(i,void 0,!1)}t._onChange(r),i._onChange(o),Object.defineProperties(this,{position:{configurable:!0,enumerable:!0,value:e},rotation:{configurable:!0,enumerable:!0,value:t},quaternion:{configurable:!0,enumerable:!0,value:i},scale:{configurable:!0,enumerable:!0,value:s},modelViewMatrix:{value:new en},normalMatrix:{value:new ot}}),this.matrix=new en,this.matrixWorld=new en,this.matrixAutoUpdate=n.DEFAULT_MATRIX_AUTO_UPDATE,this.matrixWorldAutoUpdate=n.DEFAULT_MATRIX_WORLD_AUTO_UPDATE,this.matrixWorldNeedsUpdate=!1,this.layers=new Aa,this.visible=!0,this.castShadow=!1,this.receiveShadow=!1,this.frustumCulled=!0,this.renderOrder=0,this.animations=[],this.customDepthMaterial=void 0,this.customDistanceMaterial=void 0,this.static=!1,this.userData={},this.pivot=null}onBeforeShadow(){}onAfterShadow(){}onBeforeRender(){}onAfterRender(){}applyMatrix4(e){this.matrixAutoUpdate&&this.updateMatrix(),this.matrix.premultiply(e),this.matrix.decompose(this.position,this.quaternion,this.scale),this.pivot!==null&&this.position.copy(this.pivot).applyMatrix4(this.matrix).sub(this.pivot)}applyQuaternion(e){return this.quaternion.premultiply(e),this}setRotationFromAxisAngle(e,t){this.quaternion.setFromAxisAngle(e,t)}setRotationFromEuler(e){this.quaternion.setFromEuler(e,!0)}setRotationFromMatrix(e){this.quaternion.setFromRotationMatrix(e)}setRotationFromQuaternion(e){this.quaternion.copy(e)}rotateOnAxis(e,t){return co.setFromAxisAngle(e,t),this.quaternion.multiply(co),this}rotateOnWorldAxis(e,t){return co.setFromAxisAngle(e,t),this.quaternion.premultiply(co),this}rotateX(e){return this.rotateOnAxis(bg,e)}rotateY(e){return this.rotateOnAxis(Mg,e)}rotateZ(e){return this.rotateOnAxis(wg,e)}translateOnAxis(e,t){return Sg.copy(e).applyQuaternion(this.quaternion),this.position.add(Sg.multiplyScalar(t)),this}translateX(e){return this.translateOnAxis(bg,e)}translateY(e){return this.translateOnAxis(Mg,e)}translateZ(e){return this.translateOnAxis(wg,e)}localToWorld(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(this.matrixWorld)}worldToLocal(e){return this.updateWorldMatrix(!0,!1),e.applyMatrix4(ms.copy(this.matrixWorld).invert())}lookAt(e,t,i){e.isVector3?Vl.copy(e):Vl.set(e,t,i);let s=this.parent;this.updateWorldMatrix(!0,!1),da.setFromMatrixPosition(this.matrixWorld),this.isCamera||this.isLight?ms.lookAt(da,Vl,this.up):ms.lookAt(Vl,da,this.up),this.quaternion.setFromRotationMatrix(ms),s&&(ms.extractRotation(s.matrixWorld),co.setFromRotationMatrix(ms),this.quaternion.premultiply(co.invert()))}add(e){if(arguments.length>1){for(let t=0;t<arguments.length;t++)this.add(arguments[t]);return this}return e===this?(rt("Object3D.add: object can't be added as a child of itself.",e),this):(e&&e.isObject3D?(e.removeFromParent(),e.parent=this,this.children.push(e),e.dispatchEvent(Eg),ho.child=e,this.dispatchEvent(ho),ho.child=null):rt("Object3D.add: object not an instance of THREE.Object3D.",e),this)}remove(e){if(arguments.length>1){for(let i=0;i<arguments.length;i++)this.remove(arguments[i]);return this}let t=this.children.indexOf(e);return t!==-1&&(e.parent=null,this.children.splice(t,1),e.dispatchEvent(Rv),of.child=e,this.dispatchEvent(of),of.child=null),this}removeFromParent(){let e=this.parent;return e!==null&&e.remove(this),this}clear(){return this.remove(...this.children)}attach(e){return this.updateWorldMatrix(!0,!1),ms.copy(this.matrixWorld).invert(),e.parent!==null&&(e.parent.updateWorldMatrix(!0,!1),ms.multiply(e.parent.matrixWorld)),e.applyMatrix4(ms),e.removeFromParent(),e.parent=this,this.children.push(e),e.updateWorldMatrix(!1,!0),e.dispatchEvent(Eg),ho.child=e,this.dispatchEvent(ho),ho.child=null,this}getObjectById(e){return this.getObjectByProperty("id",e)}getObjectByName(e){return this.getObjectByProperty("name",e)}getObjectByProperty(e,t){if(this[e]===t)return this;for(let i=0,s=this.children.length;i<s;i++){let o=this.children[i].getObjectByProperty(e,t);if(o!==void 0)return o}}getObjectsByProperty(e,t,i=[]){this[e]===t&&i.push(this);let s=this.children;for(let r=0,o=s.length;r<o;r++)s[r].getObjectsByProperty(e,t,i);return i}getWorldPosition(e){return this.updateWorldMatrix(!0,!1),e.setFromMatrixPosition(this.matrixWorld)}getWorldQuaternion(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(da,e,Tv),e}getWorldScale(e){return this.updateWorldMatrix(!0,!1),this.matrixWorld.decompose(da,Av,e),e}getWorldDirection(e){this.updateWorldMatrix(!0,!1);let t=this.matrixWorld.elements;return e.set(t[8],t[9],t[10]).normalize()}raycast(){}intersectsFrustum(){return!0}traverse(e){e(this);let t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].traverse(e)}traverseVisible(e){if(this.visible===!1)return;e(this);let t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].traverseVisible(e)}traverseAncestors(e){let t=this.parent;t!==null&&(e(t),t.traverseAncestors(e))}updateMatrix(){this.matrix.compose(this.position,this.quaternion,this.scale);let e=this.pivot;if(e!==null){let t=e.x,i=e.y,s=e.z,r=this.matrix.elements;r[12]+=t-r[0]*t-r[4]*i-r[8]*s,r[13]+=i-r[1]*t-r[5]*i-r[9]*s,r[14]+=s-r[2]*t-r[6]*i-r[10]*s}this.matrixWorldNeedsUpdate=!0}updateMatrixWorld(e){this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||e)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,e=!0);let t=this.children;for(let i=0,s=t.length;i<s;i++)t[i].updateMatrixWorld(e)}updateWorldMatrix(e,t,i=!1){let s=this.parent;if(e===!0&&s!==null&&s.updateWorldMatrix(!0,!1),this.matrixAutoUpdate&&this.updateMatrix(),(this.matrixWorldNeedsUpdate||i)&&(this.matrixWorldAutoUpdate===!0&&(this.parent===null?this.matrixWorld.copy(this.matrix):this.matrixWorld.multiplyMatrices(this.parent.matrixWorld,this.matrix)),this.matrixWorldNeedsUpdate=!1,i=!0),t===!0){let r=this.children;for(let o=0,a=r.length;o<a;o++)r[o].updateWorldMatrix(!1,!0,i)}}toJSON(e){let t=e===void 0||typeof e=="string",i={};t&&(e={geometries:{},materials:{},textures:{},images:{},shapes:{},skeletons:{},animations:{},nodes:{}},i.metadata={version:4.7,type:"Object",generator:"Object3D.toJSON"});let s={};s.uuid=this.uuid,s.type=this.type,s.name=this.name,s.castShadow=this.castShadow,s.receiveShadow=this.receiveShadow,s.visible=this.visible,s.frustumCulled=this.frustumCulled,s.renderOrder=this.renderOrder,s.static=this.static,s.matrixAutoUpdate=this.matrixAutoUpdate,Object.keys(this.userData).length>0&&(s.userData=this.userData),s.layers=this.layers.mask,s.matrix=this.matrix.toArray(),s.up=this.up.toArray(),this.pivot!==null&&(s.pivot=this.pivot.toArray()),this.morphTargetDictionary!==void 0&&(s.morphTargetDictionary=Object.assign({},this.morphTargetDictionary)),this.morphTargetInfluences!==void 0&&(s.morphTargetInfluences=this.morphTargetInfluences.slice()),this.isInstancedMesh&&(s.type="InstancedMesh",s.count=this.count,s.instanceMatrix=this.instanceMatrix.toJSON(),this.instanceColor!==null&&(s.instanceColor=this.instanceColor.toJSON())),this.isBatchedMesh&&(s.type="BatchedMesh",s.perObjectFrustumCulled=this.perObjectFrustumCulled,s.sortObjects=this.sortObjects,s.drawRanges=this._drawRanges,s.reservedRanges=this._reservedRanges,s.geometryInfo=this._geometryInfo.map(a=>({...a,boundingBox:a.boundingBox?a.boundingBox.toJSON():void 0,boundingSphere:a.boundingSphere?a.boundingSphere.toJSON():void 0})),s.instanceInfo=this._instanceInfo.map(a=>({...a})),s.availableInstanceIds=this._availableInstanceIds.slice(),s.availableGeometryIds=this._availableGeometryIds.slice(),s.nextIndexStart=this._nextIndexStart,s.nextVertexStart=this._nextVertexStart,s.geometryCount=this._geometryCount,s.maxInstanceCount=this._maxInstanceCount,s.maxVertexCount=this._maxVertexCount,s.maxIndexCount=this._maxIndexCount,s.geometryInitialized=this._geometryInitialized,s.matricesTexture=this._matricesTexture.toJSON(e),s.indirectTexture=this._indirectTexture.toJSON(e),this._colorsTexture!==null&&(s.colorsTexture=this._colorsTexture.toJSON(e)),this.boundingSphere!==null&&(s.boundingSphere=this.boundingSphere.toJSON()),this.boundingBox!==null&&(s.boundingBox=this.boundingBox.toJSON()));function r(a,l){return a[l.uuid]===void 0&&(a[l.uuid]=l.toJSON(e)),l.uuid}if(this.isScene)this.background&&(this.background.isColor?s.background=this.background.toJSON():this.background.isTexture&&(s.background=this.background.toJSON(e).uuid)),this.environment&&this.environment.isTexture&&this.environment.isRenderTargetTexture!==!0&&(s.environment=this.environment.toJSON(e).uuid);else if(this.isMesh||this.isLine||this.isPoints){s.geometry=r(e.geometries,this.geometry);let a=this.geometry.parameters;if(a!==void 0&&a.shapes!==void 0){let l=a.shapes;if(Array.isArray(l))for(let c=0,h=l.length;c<h;c++){let f=l[c];r(e.shapes,f)}else r(e.shapes,l)}}if(this.isSkinnedMesh&&(s.bindMode=this.bindMode,s.bindMatrix=this.bindMatrix.toArray(),this.skeleton!==void 0&&(r(e.skeletons,this.skeleton),s.skeleton=this.skeleton.uuid)),this.material!==void 0)if(Array.isArray(this.material)){let a=[];for(let l=0,c=this.material.length;l<c;l++)a.push(r(e.materials,this.material[l]));s.material=a}else s.material=r(e.materials,this.material);if(this.children.length>0){s.children=[];for(let a=0;a<this.children.length;a++)s.children.push(this.children[a].toJSON(e).object)}if(this.animations.length>0){s.animations=[];for(let a=0;a<this.animations.length;a++){let l=this.animations[a];s.animations.push(r(e.animations,l))}}if(t){let a=o(e.geometries),l=o(e.materials),c=o(e.textures),h=o(e.images),f=o(e.shapes),u=o(e.skeletons),p=o(e.animations),g=o(e.nodes);a.length>0&&(i.geometries=a),l.length>0&&(i.materials=l),c.length>0&&(i.textures=c),h.length>0&&(i.images=h),f.length>0&&(i.shapes=f),u.length>0&&(i.skeletons=u),p.length>0&&(i.animations=p),g.length>0&&(i.nodes=g)}return i.object=s,i;function o(a){let l=[];for(let c in a){let h=a[c];delete h.metadata,l.push(h)}return l}}clone(e){return new this.constructor().copy(this,e)}copy(e,t=!0){if(this.name=e.name,this.up.copy(e.up),this.position.copy(e.position),this.rotation.order=e.rotation.order,this.quaternion.copy(e.quaternion),this.scale.copy(e.scale),this.pivot=e.pivot!==null?e.pivot.clone():null,this.matrix.copy(e.matrix),this.matrixWorld.copy(e.matrixWorld),this.matrixAutoUpdate=e.matrixAutoUpdate,this.matrixWorldAutoUpdate=e.matrixWorldAutoUpdate,this.matrixWorldNeedsUpdate=e.matrixWorldNeedsUpdate,this.layers.mask=e.layers.mask,this.visible=e.visible,this.castShadow=e.castShadow,this.receiveShadow=e.receiveShadow,this.frustumCulled=e.frustumCulled,this.renderOrder=e.renderOrder,this.static=e.static,this.animations=e.animations.slice(),this.userData=JSON.parse(JSON.stringify(e.userData)),t===!0)for(let i=0;i<e.children.length;i++){let s=e.children[i];this.add(s.clone())}return this}dispose(){this.dispatchEvent({type:"dispose"})}};Jn.DEFAULT_UP=new K(0,1,0);Jn.DEFAULT_MATRIX_AUTO_UPDATE=!0;Jn.DEFAULT_MATRIX_WORLD_AUTO_UPDATE=!0;var Tr=class extends Jn{constructor(){super(),this.isGroup=!0,this.type="Group"}},Cv={type:"move"},To=class{constructor(){this._targetRay=null,this._grip=null,this._hand=null}getHandSpace(){return this._hand===null&&(this._hand=new Tr,this._hand.matrixAutoUpdate=!1,this._hand.visible=!1,this._hand.joints={},this._hand.inputState={pinching:!1}),this._hand}getTargetRaySpace(){return this._targetRay===null&&(this._targetRay=new Tr,this._targetRay.matrixAutoUpdate=!1,this._targetRay.visible=!1,this._targetRay.hasLinearVelocity=!1,this._targetRay.linearVelocity=new K,this._targetRay.hasAngularVelocity=!1,this._targetRay.angularVelocity=new K),this._targetRay}getGripSpace(){return this._grip===null&&(this._grip=new Tr,this._grip.matrixAutoUpdate=!1,this._grip.visible=!1,this._grip.hasLinearVelocity=!1,this._grip.linearVelocity=new K,this._grip.hasAngularVelocity=!1,this._grip.angularVelocity=new K,this._grip.eventsEnabled=!1),this._grip}dispatchEvent(e){return this._targetRay!==null&&this._targetRay.dispatchEvent(e),this._grip!==null&&this._grip.dispatchEvent(e),this._hand!==null&&this._hand.dispatchEvent(e),this}connect(e){if(e&&e.hand){let t=this._hand;if(t)for(let i of e.hand.values())this._getHandJoint(t,i)}return this.dispatchEvent({type:"connected",data:e}),this}disconnect(e){return this.dispatchEvent({type:"disconnected",data:e}),this._targetRay!==null&&(this._targetRay.visible=!1),this._grip!==null&&(this._grip.visible=!1),this._hand!==null&&(this._hand.visible=!1),this}update(e,t,i){let s=null,r=null,o=null,a=this._targetRay,l=this._grip,c=this._hand;if(e&&t.session.visibilityState!=="visible-blurred"){if(c&&e.hand){o=!0;for(let S of e.hand.values()){let d=t.getJointPose(S,i),m=this._getHandJoint(c,S);d!==null&&(m.matrix.fromArray(d.transform.matrix),m.matrix.decompose(m.position,m.quaternion,m.scale),m.matrixWorldNeedsUpdate=!0,m.jointRadius=d.radius),m.visible=d!==null}let h=c.joints["index-finger-tip"],f=c.joints["thumb-tip"],u=h.position.distanceTo(f.position),p=.02,g=.005;c.inputState.pinching&&u>p+g?(c.inputState.pinching=!1,this.dispatchEvent({type:"pinchend",handedness:e.handedness,target:this})):!c.inputState.pinching&&u<=p-g&&(c.inputState.pinching=!0,this.dispatchEvent({type:"pinchstart",handedness:e.handedness,target:this}))}else l!==null&&e.gripSpace&&(r=t.getPose(e.gripSpace,i),r!==null&&(l.matrix.fromArray(r.transform.matrix),l.matrix.decompose(l.position,l.quaternion,l.scale),l.matrixWorldNeedsUpdate=!0,r.linearVelocity?(l.hasLinearVelocity=!0,l.linearVelocity.copy(r.linearVelocity)):l.hasLinearVelocity=!1,r.angularVelocity?(l.hasAngularVelocity=!0,l.angularVelocity.copy(r.angularVelocity)):l.hasAngularVelocity=!1,l.eventsEnabled&&l.dispatchEvent({type:"gripUpdated",data:e,target:this})));a!==null&&(s=t.getPose(e.targetRaySpace,i),s===null&&r!==null&&(s=r),s!==null&&(a.matrix.fromArray(s.transform.matrix),a.matrix.decompose(a.position,a.quaternion,a.scale),a.matrixWorldNeedsUpdate=!0,s.linearVelocity?(a.hasLinearVelocity=!0,a.linearVelocity.copy(s.linearVelocity)):a.hasLinearVelocity=!1,s.angularVelocity?(a.hasAngularVelocity=!0,a.angularVelocity.copy(s.angularVelocity)):a.hasAngularVelocity=!1,this.dispatchEvent(Cv)))}return a!==null&&(a.visible=s!==null),l!==null&&(l.visible=r!==null),c!==null&&(c.visible=o!==null),this}_getHandJoint(e,t){if(e.joints[t.jointName]===void 0){let i=new Tr;i.matrixAutoUpdate=!1,i.visible=!1,e.joints[t.jointName]=i,e.add(i)}return e.joints[t.jointName]}},A0={aliceblue:15792383,antiquewhite:16444375,aqua:65535,aquamarine:8388564,azure:15794175,beige:16119260,bisque:16770244,black:0,blanchedalmond:16772045,blue:255,blueviolet:9055202,brown:10824234,burlywood:14596231,cadetblue:6266528,chartreuse:8388352,chocolate:13789470,coral:16744272,cornflowerblue:6591981,cornsilk:16775388,crimson:14423100,cyan:65535,darkblue:139,darkcyan:35723,darkgoldenrod:12092939,darkgray:11119017,darkgreen:25600,darkgrey:11119017,darkkhaki:12433259,darkmagenta:9109643,darkolivegreen:5597999,darkorange:16747520,darkorchid:10040012,darkred:9109504,darksalmon:15308410,darkseagreen:9419919,darkslateblue:4734347,darkslategray:3100495,darkslategrey:3100495,darkturquoise:52945,darkviolet:9699539,deeppink:16716947,deepskyblue:49151,dimgray:6908265,dimgrey:6908265,dodgerblue:2003199,firebrick:11674146,floralwhite:16775920,forestgreen:2263842,fuchsia:16711935,gainsboro:14474460,ghostwhite:16316671,gold:16766720,goldenrod:14329120,gray:8421504,green:32768,greenyellow:11403055,grey:8421504,honeydew:15794160,hotpink:16738740,indianred:13458524,indigo:4915330,ivory:16777200,khaki:15787660,lavender:15132410,lavenderblush:16773365,lawngreen:8190976,lemonchiffon:16775885,lightblue:11393254,lightcoral:15761536,lightcyan:14745599,lightgoldenrodyellow:16448210,lightgray:13882323,lightgreen:9498256,lightgrey:13882323,lightpink:16758465,lightsalmon:16752762,lightseagreen:2142890,lightskyblue:8900346,lightslategray:7833753,lightslategrey:7833753,lightsteelblue:11584734,lightyellow:16777184,lime:65280,limegreen:3329330,linen:16445670,magenta:16711935,maroon:8388608,mediumaquamarine:6737322,mediumblue:205,mediumorchid:12211667,mediumpurple:9662683,mediumseagreen:3978097,mediumslateblue:8087790,mediumspringgreen:64154,mediumturquoise:4772300,mediumvioletred:13047173,midnightblue:1644912,mintcream:16121850,mistyrose:16770273,moccasin:16770229,navajowhite:16768685,navy:128,oldlace:16643558,olive:8421376,olivedrab:7048739,orange:16753920,orangered:16729344,orchid:14315734,palegoldenrod:15657130,palegreen:10025880,paleturquoise:11529966,palevioletred:14381203,papayawhip:16773077,peachpuff:16767673,peru:13468991,pink:16761035,plum:14524637,powderblue:11591910,purple:8388736,rebeccapurple:6697881,red:16711680,rosybrown:12357519,royalblue:4286945,saddlebrown:9127187,salmon:16416882,sandybrown:16032864,seagreen:3050327,seashell:16774638,sienna:10506797,silver:12632256,skyblue:8900331,slateblue:6970061,slategray:7372944,slategrey:7372944,snow:16775930,springgreen:65407,steelblue:4620980,tan:13808780,teal:32896,thistle:14204888,tomato:16737095,turquoise:4251856,violet:15631086,wheat:16113331,white:16777215,whitesmoke:16119285,yellow:16776960,yellowgreen:10145074},Xs={h:0,s:0,l:0},Wl={h:0,s:0,l:0};function af(n,e,t){return t<0&&(t+=1),t>1&&(t-=1),t<1/6?n+(e-n)*6*t:t<1/2?e:t<2/3?n+(e-n)*6*(2/3-t):n}var gt=class{constructor(e,t,i){return this.isColor=!0,this.r=1,this.g=1,this.b=1,this.set(e,t,i)}set(e,t,i){if(t===void 0&&i===void 0){let s=e;s&&s.isColor?this.copy(s):typeof s=="number"?this.setHex(s):typeof s=="string"&&this.setStyle(s)}else this.setRGB(e,t,i);return this}setScalar(e){return this.r=e,this.g=e,this.b=e,this}setHex(e,t=hi){return e=Math.floor(e),this.r=(e>>16&255)/255,this.g=(e>>8&255)/255,this.b=(e&255)/255,At.colorSpaceToWorking(this,t),this}setRGB(e,t,i,s=At.workingColorSpace){return this.r=e,this.g=t,this.b=i,At.colorSpaceToWorking(this,s),this}setHSL(e,t,i,s=At.workingColorSpace){if(e=id(e,1),t=St(t,0,1),i=St(i,0,1),t===0)this.r=this.g=this.b=i;else{let r=i<=.5?i*(1+t):i+t-i*t,o=2*i-r;this.r=af(o,r,e+1/3),this.g=af(o,r,e),this.b=af(o,r,e-1/3)}return At.colorSpaceToWorking(this,s),this}setStyle(e,t=hi){function i(r){r!==void 0&&parseFloat(r)<1&&Je("Color: Alpha component of "+e+" will be ignored.")}let s;if(s=/^(\w+)\(([^\)]*)\)/.exec(e)){let r,o=s[1],a=s[2];switch(o){case"rgb":case"rgba":if(r=/^\s*(\d+)\s*,\s*(\d+)\s*,\s*(\d+)\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(r[4]),this.setRGB(Math.min(255,parseInt(r[1],10))/255,Math.min(255,parseInt(r[2],10))/255,Math.min(255,parseInt(r[3],10))/255,t);if(r=/^\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(r[4]),this.setRGB(Math.min(100,parseFloat(r[1]))/100,Math.min(100,parseFloat(r[2]))/100,Math.min(100,parseFloat(r[3]))/100,t);break;case"hsl":case"hsla":if(r=/^\s*([+-]?(?:\d+(?:\.\d+)?|\.\d+))\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*,\s*(\d+(?:\.\d+)?|\.\d+)\%\s*(?:,\s*(\d+(?:\.\d+)?|\.\d+)\s*)?$/.exec(a))return i(r[4]),this.setHSL(parseFloat(r[1])/360,parseFloat(r[2])/100,parseFloat(r[3])/100,t);break;default:Je("Color: Unknown color model "+e)}}else if(s=/^\#([A-Fa-f\d]+)$/.exec(e)){let r=s[1],o=r.length;if(o===3)return this.setRGB(parseInt(r.charAt(0),16)/15,parseInt(r.charAt(1),16)/15,parseInt(r.charAt(2),16)/15,t);if(o===6)return this.setHex(parseInt(r,16),t);Je("Color: Invalid hex color "+e)}else if(e&&e.length>0)return this.setColorName(e,t);return this}setColorName(e,t=hi){let i=A0[e.toLowerCase()];return i!==void 0?this.setHex(i,t):Je("Color: Unknown color "+e),this}clone(){return new this.constructor(this.r,this.g,this.b)}copy(e){return this.r=e.r,this.g=e.g,this.b=e.b,this}copySRGBToLinear(e){return this.r=vs(e.r),this.g=vs(e.g),this.b=vs(e.b),this}copyLinearToSRGB(e){return this.r=So(e.r),this.g=So(e.g),this.b=So(e.b),this}convertSRGBToLinear(){return this.copySRGBToLinear(this),this}convertLinearToSRGB(){return this.copyLinearToSRGB(this),this}getHex(e=hi){return At.workingToColorSpace(Bn.copy(this),e),Math.round(St(Bn.r*255,0,255))*65536+Math.round(St(Bn.g*255,0,255))*256+Math.round(St(Bn.b*255,0,255))}getHexString(e=hi){return("000000"+this.getHex(e).toString(16)).slice(-6)}getHSL(e,t=At.workingColorSpace){At.workingToColorSpace(Bn.copy(this),t);let i=Bn.r,s=Bn.g,r=Bn.b,o=Math.max(i,s,r),a=Math.min(i,s,r),l,c,h=(a+o)/2;if(a===o)l=0,c=0;else{let f=o-a;switch(c=h<=.5?f/(o+a):f/(2-o-a),o){case i:l=(s-r)/f+(s<r?6:0);break;case s:l=(r-i)/f+2;break;case r:l=(i-s)/f+4;break}l/=6}return e.h=l,e.s=c,e.l=h,e}getRGB(e,t=At.workingColorSpace){return At.workingToColorSpace(Bn.copy(this),t),e.r=Bn.r,e.g=Bn.g,e.b=Bn.b,e}getStyle(e=hi){At.workingToColorSpace(Bn.copy(this),e);let t=Bn.r,i=Bn.g,s=Bn.b;return e!==hi?`color(${e} ${t.toFixed(3)} ${i.toFixed(3)} ${s.toFixed(3)})`:`rgb(${Math.round(t*255)},${Math.round(i*255)},${Math.round(s*255)})`}offsetHSL(e,t,i){return this.getHSL(Xs),this.setHSL(Xs.h+e,Xs.s+t,Xs.l+i)}add(e){return this.r+=e.r,this.g+=e.g,this.b+=e.b,this}addColors(e,t){return this.r=e.r+t.r,this.g=e.g+t.g,this.b=e.b+t.b,this}addScalar(e){return this.r+=e,this.g+=e,this.b+=e,this}sub(e){return this.r=Math.max(0,this.r-e.r),this.g=Math.max(0,this.g-e.g),this.b=Math.max(0,this.b-e.b),this}multiply(e){return this.r*=e.r,this.g*=e.g,this.b*=e.b,this}multiplyScalar(e){return this.r*=e,this.g*=e,this.b*=e,this}lerp(e,t){return this.r+=(e.r-this.r)*t,this.g+=(e.g-this.g)*t,this.b+=(e.b-this.b)*t,this}lerpColors(e,t,i){return this.r=e.r+(t.r-e.r)*i,this.g=e.g+(t.g-e.g)*i,this.b=e.b+(t.b-e.b)*i,this}lerpHSL(e,t){this.getHSL(Xs),e.getHSL(Wl);let i=va(Xs.h,Wl.h,t),s=va(Xs.s,Wl.s,t),r=va(Xs.l,Wl.l,t);return this.setHSL(i,s,r),this}setFromVector3(e){return this.r=e.x,this.g=e.y,this.b=e.z,this}applyMatrix3(e){let t=this.r,i=this.g,s=this.b,r=e.elements;return this.r=r[0]*t+r[3]*i+r[6]*s,this.g=r[1]*t+r[4]*i+r[7]*s,this.b=r[2]*t+r[5]*i+r[8]*s,this}equals(e){return e.r===this.r&&e.g===this.g&&e.b===this.b}fromArray(e,t=0){return this.r=e[t],this.g=e[t+1],this.b=e[t+2],this}toArray(e=[],t=0){return e[t]=this.r,e[t+1]=this.g,e[t+2]=this.b,e}fromBufferAttribute(e,t){return this.r=e.getX(t),this.g=e.getY(t),this.b=e.getZ(t),this}toJSON(){return this.getHex()}*[Symbol.iterator](){yield this.r,yield this.g,yield this.b}},Bn=new gt;gt.NAMES=A0;var Ra=class extends Jn{constructor(){super(),this.isScene=!0,this.type="Scene",this.background=null,this.environment=null,this.fog=null,this.backgroundBlurriness=0,this.backgroundIntensity=1,this.backgroundRotation=new Ks,this.environmentIntensity=1,this.environmentRotation=new Ks,this.overrideMaterial=null,typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}copy(e,t){return super.copy(e,t),this.background=e.background!==null?e.background.clone():null,this.environment=e.environment!==null?e.environment.clone():null,this.fog=e.fog!==null?e.fog.clone():null,this.backgroundBlurriness=e.backgroundBlurriness,this.backgroundIntensity=e.backgroundIntensity,this.backgroundRotation.copy(e.backgroundRotation),this.environmentIntensity=e.environmentIntensity,this.environmentRotation.copy(e.environmentRotation),this.overrideMaterial=e.overrideMaterial!==null?e.overrideMaterial.clone():null,this.matrixAutoUpdate=e.matrixAutoUpdate,this}toJSON(e){let t=super.toJSON(e);return this.fog!==null&&(t.object.fog=this.fog.toJSON()),t.object.backgroundBlurriness=this.backgroundBlurriness,t.object.backgroundIntensity=this.backgroundIntensity,t.object.backgroundRotation=this.backgroundRotation.toArray(),t.object.environmentIntensity=this.environmentIntensity,t.object.environmentRotation=this.environmentRotation.toArray(),t}},Li=new K,gs=new K,lf=new K,_s=new K,uo=new K,fo=new K,Tg=new K,cf=new K,hf=new K,uf=new K,ff=new sn,df=new sn,pf=new sn,Zs=class n{constructor(e=new K,t=new K,i=new K){this.a=e,this.b=t,this.c=i}static getNormal(e,t,i,s){s.subVectors(i,t),Li.subVectors(e,t),s.cross(Li);let r=s.lengthSq();return r>0?s.multiplyScalar(1/Math.sqrt(r)):s.set(0,0,0)}static getBarycoord(e,t,i,s,r){Li.subVectors(s,t),gs.subVectors(i,t),lf.subVectors(e,t);let o=Li.dot(Li),a=Li.dot(gs),l=Li.dot(lf),c=gs.dot(gs),h=gs.dot(lf),f=o*c-a*a;if(f===0)return r.set(0,0,0),null;let u=1/f,p=(c*l-a*h)*u,g=(o*h-a*l)*u;return r.set(1-p-g,g,p)}static containsPoint(e,t,i,s){return this.getBarycoord(e,t,i,s,_s)===null?!1:_s.x>=0&&_s.y>=0&&_s.x+_s.y<=1}static getInterpolation(e,t,i,s,r,o,a,l){return this.getBarycoord(e,t,i,s,_s)===null?(l.x=0,l.y=0,"z"in l&&(l.z=0),"w"in l&&(l.w=0),null):(l.setScalar(0),l.addScaledVector(r,_s.x),l.addScaledVector(o,_s.y),l.addScaledVector(a,_s.z),l)}static getInterpolatedAttribute(e,t,i,s,r,o){return ff.setScalar(0),df.setScalar(0),pf.setScalar(0),ff.fromBufferAttribute(e,t),df.fromBufferAttribute(e,i),pf.fromBufferAttribute(e,s),o.setScalar(0),o.addScaledVector(ff,r.x),o.addScaledVector(df,r.y),o.addScaledVector(pf,r.z),o}static isFrontFacing(e,t,i,s){return Li.subVectors(i,t),gs.subVectors(e,t),Li.cross(gs).dot(s)<0}set(e,t,i){return this.a.copy(e),this.b.copy(t),this.c.copy(i),this}setFromPointsAndIndices(e,t,i,s){return this.a.copy(e[t]),this.b.copy(e[i]),this.c.copy(e[s]),this}setFromAttributeAndIndices(e,t,i,s){return this.a.fromBufferAttribute(e,t),this.b.fromBufferAttribute(e,i),this.c.fromBufferAttribute(e,s),this}clone(){return new this.constructor().copy(this)}copy(e){return this.a.copy(e.a),this.b.copy(e.b),this.c.copy(e.c),this}getArea(){return Li.subVectors(this.c,this.b),gs.subVectors(this.a,this.b),Li.cross(gs).length()*.5}getMidpoint(e){return e.addVectors(this.a,this.b).add(this.c).multiplyScalar(1/3)}getNormal(e){return n.getNormal(this.a,this.b,this.c,e)}getPlane(e){return e.setFromCoplanarPoints(this.a,this.b,this.c)}getBarycoord(e,t){return n.getBarycoord(e,this.a,this.b,this.c,t)}getInterpolation(e,t,i,s,r){return n.getInterpolation(e,this.a,this.b,this.c,t,i,s,r)}containsPoint(e){return n.containsPoint(e,this.a,this.b,this.c)}isFrontFacing(e){return n.isFrontFacing(this.a,this.b,this.c,e)}intersectsBox(e){return e.intersectsTriangle(this)}closestPointToPoint(e,t){let i=this.a,s=this.b,r=this.c,o,a;uo.subVectors(s,i),fo.subVectors(r,i),cf.subVectors(e,i);let l=uo.dot(cf),c=fo.dot(cf);if(l<=0&&c<=0)return t.copy(i);hf.subVectors(e,s);let h=uo.dot(hf),f=fo.dot(hf);if(h>=0&&f<=h)return t.copy(s);let u=l*f-h*c;if(u<=0&&l>=0&&h<=0&&l-h>0)return o=l/(l-h),t.copy(i).addScaledVector(uo,o);uf.subVectors(e,r);let p=uo.dot(uf),g=fo.dot(uf);if(g>=0&&p<=g)return t.copy(r);let S=p*c-l*g;if(S<=0&&c>=0&&g<=0)return a=c/(c-g),t.copy(i).addScaledVector(fo,a);let d=h*g-p*f;if(d<=0&&f-h>=0&&p-g>=0)return Tg.subVectors(r,s),a=(f-h)/(f-h+(p-g)),t.copy(s).addScaledVector(Tg,a);let m=1/(d+S+u);return o=S*m,a=u*m,t.copy(i).addScaledVector(uo,o).addScaledVector(fo,a)}equals(e){return e.a.equals(this.a)&&e.b.equals(this.b)&&e.c.equals(this.c)}},Js=class{constructor(e=new K(1/0,1/0,1/0),t=new K(-1/0,-1/0,-1/0)){this.isBox3=!0,this.min=e,this.max=t}set(e,t){return this.min.copy(e),this.max.copy(t),this}setFromArray(e){this.makeEmpty();for(let t=0,i=e.length;t<i;t+=3)this.expandByPoint(Ni.fromArray(e,t));return this}setFromBufferAttribute(e){this.makeEmpty();for(let t=0,i=e.count;t<i;t++)this.expandByPoint(Ni.fromBufferAttribute(e,t));return this}setFromPoints(e){this.makeEmpty();for(let t=0,i=e.length;t<i;t++)this.expandByPoint(e[t]);return this}setFromCenterAndSize(e,t){let i=Ni.copy(t).multiplyScalar(.5);return this.min.copy(e).sub(i),this.max.copy(e).add(i),this}setFromObject(e,t=!1){return this.makeEmpty(),this.expandByObject(e,t)}clone(){return new this.constructor().copy(this)}copy(e){return this.min.copy(e.min),this.max.copy(e.max),this}makeEmpty(){return this.min.x=this.min.y=this.min.z=1/0,this.max.x=this.max.y=this.max.z=-1/0,this}isEmpty(){return this.max.x<this.min.x||this.max.y<this.min.y||this.max.z<this.min.z}getCenter(e){return this.isEmpty()?e.set(0,0,0):e.addVectors(this.min,this.max).multiplyScalar(.5)}getSize(e){return this.isEmpty()?e.set(0,0,0):e.subVectors(this.max,this.min)}expandByPoint(e){return this.min.min(e),this.max.max(e),this}expandByVector(e){return this.min.sub(e),this.max.add(e),this}expandByScalar(e){return this.min.addScalar(-e),this.max.addScalar(e),this}expandByObject(e,t=!1){e.updateWorldMatrix(!1,!1);let i=e.geometry;if(i!==void 0){let r=i.getAttribute("position");if(t===!0&&r!==void 0&&e.isInstancedMesh!==!0&&e.isBatchedMesh!==!0)for(let o=0,a=r.count;o<a;o++)e.isMesh===!0?e.getVertexPosition(o,Ni):Ni.fromBufferAttribute(r,o),Ni.applyMatrix4(e.matrixWorld),this.expandByPoint(Ni);else e.boundingBox!==void 0?(e.boundingBox===null&&e.computeBoundingBox(),Xl.copy(e.boundingBox)):(i.boundingBox===null&&i.computeBoundingBox(),Xl.copy(i.boundingBox)),Xl.applyMatrix4(e.matrixWorld),this.union(Xl)}let s=e.children;for(let r=0,o=s.length;r<o;r++)this.expandByObject(s[r],t);return this}containsPoint(e){return e.x>=this.min.x&&e.x<=this.max.x&&e.y>=this.min.y&&e.y<=this.max.y&&e.z>=this.min.z&&e.z<=this.max.z}containsBox(e){return this.min.x<=e.min.x&&e.max.x<=this.max.x&&this.min.y<=e.min.y&&e.max.y<=this.max.y&&this.min.z<=e.min.z&&e.max.z<=this.max.z}getParameter(e,t){return t.set((e.x-this.min.x)/(this.max.x-this.min.x),(e.y-this.min.y)/(this.max.y-this.min.y),(e.z-this.min.z)/(this.max.z-this.min.z))}intersectsBox(e){return e.max.x>=this.min.x&&e.min.x<=this.max.x&&e.max.y>=this.min.y&&e.min.y<=this.max.y&&e.max.z>=this.min.z&&e.min.z<=this.max.z}intersectsSphere(e){return this.clampPoint(e.center,Ni),Ni.distanceToSquared(e.center)<=e.radius*e.radius}intersectsPlane(e){let t,i;return e.normal.x>0?(t=e.normal.x*this.min.x,i=e.normal.x*this.max.x):(t=e.normal.x*this.max.x,i=e.normal.x*this.min.x),e.normal.y>0?(t+=e.normal.y*this.min.y,i+=e.normal.y*this.max.y):(t+=e.normal.y*this.max.y,i+=e.normal.y*this.min.y),e.normal.z>0?(t+=e.normal.z*this.min.z,i+=e.normal.z*this.max.z):(t+=e.normal.z*this.max.z,i+=e.normal.z*this.min.z),t<=-e.constant&&i>=-e.constant}intersectsTriangle(e){if(this.isEmpty())return!1;this.getCenter(pa),ql.subVectors(this.max,pa),po.subVectors(e.a,pa),mo.subVectors(e.b,pa),go.subVectors(e.c,pa),qs.subVectors(mo,po),Ys.subVectors(go,mo),br.subVectors(po,go);let t=[0,-qs.z,qs.y,0,-Ys.z,Ys.y,0,-br.z,br.y,qs.z,0,-qs.x,Ys.z,0,-Ys.x,br.z,0,-br.x,-qs.y,qs.x,0,-Ys.y,Ys.x,0,-br.y,br.x,0];return!mf(t,po,mo,go,ql)||(t=[1,0,0,0,1,0,0,0,1],!mf(t,po,mo,go,ql))?!1:(Yl.crossVectors(qs,Ys),t=[Yl.x,Yl.y,Yl.z],mf(t,po,mo,go,ql))}clampPoint(e,t){return t.copy(e).clamp(this.min,this.max)}distanceToPoint(e){return this.clampPoint(e,Ni).distanceTo(e)}getBoundingSphere(e){return this.isEmpty()?e.makeEmpty():(this.getCenter(e.center),e.radius=this.getSize(Ni).length()*.5),e}intersect(e){return this.min.max(e.min),this.max.min(e.max),this.isEmpty()&&this.makeEmpty(),this}union(e){return this.min.min(e.min),this.max.max(e.max),this}applyMatrix4(e){return this.isEmpty()?this:(xs[0].set(this.min.x,this.min.y,this.min.z).applyMatrix4(e),xs[1].set(this.min.x,this.min.y,this.max.z).applyMatrix4(e),xs[2].set(this.min.x,this.max.y,this.min.z).applyMatrix4(e),xs[3].set(this.min.x,this.max.y,this.max.z).applyMatrix4(e),xs[4].set(this.max.x,this.min.y,this.min.z).applyMatrix4(e),xs[5].set(this.max.x,this.min.y,this.max.z).applyMatrix4(e),xs[6].set(this.max.x,this.max.y,this.min.z).applyMatrix4(e),xs[7].set(this.max.x,this.max.y,this.max.z).applyMatrix4(e),this.setFromPoints(xs),this)}translate(e){return this.min.add(e),this.max.add(e),this}equals(e){return e.min.equals(this.min)&&e.max.equals(this.max)}toJSON(){return{min:this.min.toArray(),max:this.max.toArray()}}fromJSON(e){return this.min.fromArray(e.min),this.max.fromArray(e.max),this}},xs=[new K,new K,new K,new K,new K,new K,new K,new K],Ni=new K,Xl=new Js,po=new K,mo=new K,go=new K,qs=new K,Ys=new K,br=new K,pa=new K,ql=new K,Yl=new K,Mr=new K;function mf(n,e,t,i,s){for(let r=0,o=n.length-3;r<=o;r+=3){Mr.fromArray(n,r);let a=s.x*Math.abs(Mr.x)+s.y*Math.abs(Mr.y)+s.z*Math.abs(Mr.z),l=e.dot(Mr),c=t.dot(Mr),h=i.dot(Mr);if(Math.max(-Math.max(l,c,h),Math.min(l,c,h))>a)return!1}return!0}var xn=new K,$l=new ut,Iv=0,fi=class extends Di{constructor(e,t,i=!1){if(super(),Array.isArray(e))throw new TypeError("THREE.BufferAttribute: array should be a Typed Array.");this.isBufferAttribute=!0,Object.defineProperty(this,"id",{value:Iv++}),this.name="",this.array=e,this.itemSize=t,this.count=e!==void 0?e.length/t:0,this.normalized=i,this.usage=v0,this.updateRanges=[],this.gpuType=Oi,this.version=0,this._normalizationScale=e!==void 0?rd(e):void 0}onUploadCallback(){}set needsUpdate(e){e===!0&&this.version++}setUsage(e){return this.usage=e,this}addUpdateRange(e,t){this.updateRanges.push({start:e,count:t})}clearUpdateRanges(){this.updateRanges.length=0}copy(e){return this.name=e.name,this.array=new e.array.constructor(e.array),this.itemSize=e.itemSize,this.count=e.count,this.normalized=e.normalized,this.usage=e.usage,this.gpuType=e.gpuType,this._normalizationScale=e._normalizationScale,this}copyAt(e,t,i){e*=this.itemSize,i*=t.itemSize;for(let s=0,r=this.itemSize;s<r;s++)this.array[e+s]=t.array[i+s];return this}copyArray(e){return this.array.set(e),this}applyMatrix3(e){if(this.itemSize===2)for(let t=0,i=this.count;t<i;t++)$l.fromBufferAttribute(this,t),$l.applyMatrix3(e),this.setXY(t,$l.x,$l.y);else if(this.itemSize===3)for(let t=0,i=this.count;t<i;t++)xn.fromBufferAttribute(this,t),xn.applyMatrix3(e),this.setXYZ(t,xn.x,xn.y,xn.z);return this}applyMatrix4(e){for(let t=0,i=this.count;t<i;t++)xn.fromBufferAttribute(this,t),xn.applyMatrix4(e),this.setXYZ(t,xn.x,xn.y,xn.z);return this}applyNormalMatrix(e){for(let t=0,i=this.count;t<i;t++)xn.fromBufferAttribute(this,t),xn.applyNormalMatrix(e),this.setXYZ(t,xn.x,xn.y,xn.z);return this}transformDirection(e){for(let t=0,i=this.count;t<i;t++)xn.fromBufferAttribute(this,t),xn.transformDirection(e),this.setXYZ(t,xn.x,xn.y,xn.z);return this}set(e,t=0){return this.array.set(e,t),this}getComponent(e,t){let i=this.array[e*this.itemSize+t];return this.normalized&&(i=this._denormalize(i)),i}setComponent(e,t,i){return this.normalized&&(i=this._normalize(i)),this.array[e*this.itemSize+t]=i,this}getX(e){let t=this.array[e*this.itemSize];return this.normalized&&(t=this._denormalize(t)),t}setX(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize]=t,this}getY(e){let t=this.array[e*this.itemSize+1];return this.normalized&&(t=this._denormalize(t)),t}setY(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+1]=t,this}getZ(e){let t=this.array[e*this.itemSize+2];return this.normalized&&(t=this._denormalize(t)),t}setZ(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+2]=t,this}getW(e){let t=this.array[e*this.itemSize+3];return this.normalized&&(t=this._denormalize(t)),t}setW(e,t){return this.normalized&&(t=this._normalize(t)),this.array[e*this.itemSize+3]=t,this}setXY(e,t,i){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i)),this.array[e+0]=t,this.array[e+1]=i,this}setXYZ(e,t,i,s){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i),s=this._normalize(s)),this.array[e+0]=t,this.array[e+1]=i,this.array[e+2]=s,this}setXYZW(e,t,i,s,r){return e*=this.itemSize,this.normalized&&(t=this._normalize(t),i=this._normalize(i),s=this._normalize(s),r=this._normalize(r)),this.array[e+0]=t,this.array[e+1]=i,this.array[e+2]=s,this.array[e+3]=r,this}onUpload(e){return this.onUploadCallback=e,this}clone(){return new this.constructor(this.array,this.itemSize).copy(this)}toJSON(){let e={itemSize:this.itemSize,type:this.array.constructor.name,array:Array.from(this.array),normalized:this.normalized};return e.name=this.name,e.usage=this.usage,e.gpuType=this.gpuType,e}dispose(){this.dispatchEvent({type:"dispose"})}_denormalize(e){let t=this._normalizationScale;return t!==void 0?Math.max(e/t,-1):E0(e,this.array)}_normalize(e){let t=this._normalizationScale;return t!==void 0?Math.round(e*t):T0(e,this.array)}};var Ca=class extends fi{constructor(e,t,i){super(new Uint16Array(e),t,i)}};var Ia=class extends fi{constructor(e,t,i){super(new Uint32Array(e),t,i)}};var Pn=class extends fi{constructor(e,t,i){super(new Float32Array(e),t,i)}},Pv=new Js,ma=new K,gf=new K,js=class{constructor(e=new K,t=-1){this.isSphere=!0,this.center=e,this.radius=t}set(e,t){return this.center.copy(e),this.radius=t,this}setFromPoints(e,t){let i=this.center;t!==void 0?i.copy(t):Pv.setFromPoints(e).getCenter(i);let s=0;for(let r=0,o=e.length;r<o;r++)s=Math.max(s,i.distanceToSquared(e[r]));return this.radius=Math.sqrt(s),this}copy(e){return this.center.copy(e.center),this.radius=e.radius,this}isEmpty(){return this.radius<0}makeEmpty(){return this.center.set(0,0,0),this.radius=-1,this}containsPoint(e){return e.distanceToSquared(this.center)<=this.radius*this.radius}distanceToPoint(e){return e.distanceTo(this.center)-this.radius}intersectsSphere(e){let t=this.radius+e.radius;return e.center.distanceToSquared(this.center)<=t*t}intersectsBox(e){return e.intersectsSphere(this)}intersectsPlane(e){return Math.abs(e.distanceToPoint(this.center))<=this.radius}clampPoint(e,t){let i=this.center.distanceToSquared(e);return t.copy(e),i>this.radius*this.radius&&(t.sub(this.center).normalize(),t.multiplyScalar(this.radius).add(this.center)),t}getBoundingBox(e){return this.isEmpty()?(e.makeEmpty(),e):(e.set(this.center,this.center),e.expandByScalar(this.radius),e)}applyMatrix4(e){return this.center.applyMatrix4(e),this.radius=this.radius*e.getMaxScaleOnAxis(),this}translate(e){return this.center.add(e),this}expandByPoint(e){if(this.isEmpty())return this.center.copy(e),this.radius=0,this;ma.subVectors(e,this.center);let t=ma.lengthSq();if(t>this.radius*this.radius){let i=Math.sqrt(t),s=(i-this.radius)*.5;this.center.addScaledVector(ma,s/i),this.radius+=s}return this}union(e){return e.isEmpty()?this:this.isEmpty()?(this.copy(e),this):(this.center.equals(e.center)===!0?this.radius=Math.max(this.radius,e.radius):(gf.subVectors(e.center,this.center).setLength(e.radius),this.expandByPoint(ma.copy(e.center).add(gf)),this.expandByPoint(ma.copy(e.center).sub(gf))),this)}equals(e){return e.center.equals(this.center)&&e.radius===this.radius}clone(){return new this.constructor().copy(this)}toJSON(){return{radius:this.radius,center:this.center.toArray()}}fromJSON(e){return this.radius=e.radius,this.center.fromArray(e.center),this}},Lv=0,bi=new en,_f=new Jn,_o=new K,ci=new Js,ga=new Js,In=new K,jn=class n extends Di{constructor(){super(),this.isBufferGeometry=!0,Object.defineProperty(this,"id",{value:Lv++}),this.uuid=Oo(),this.name="",this.type="BufferGeometry",this.index=null,this.indirect=null,this.indirectOffset=0,this.attributes={},this.morphAttributes={},this.morphTargetsRelative=!1,this.groups=[],this.boundingBox=null,this.boundingSphere=null,this.drawRange={start:0,count:1/0},this.userData={},this._transformed=!1}getIndex(){return this.index}setIndex(e){return Array.isArray(e)?this.index=new(iv(e)?Ia:Ca)(e,1):this.index=e,this}setIndirect(e,t=0){return this.indirect=e,this.indirectOffset=t,this}getIndirect(){return this.indirect}getAttribute(e){return this.attributes[e]}setAttribute(e,t){return this.attributes[e]=t,this}deleteAttribute(e){return delete this.attributes[e],this}hasAttribute(e){return this.attributes[e]!==void 0}addGroup(e,t,i=0){this.groups.push({start:e,count:t,materialIndex:i})}clearGroups(){this.groups=[]}setDrawRange(e,t){this.drawRange.start=e,this.drawRange.count=t}applyMatrix4(e){let t=this.attributes.position;t!==void 0&&(t.applyMatrix4(e),t.needsUpdate=!0);let i=this.attributes.normal;if(i!==void 0){let r=new ot().getNormalMatrix(e);i.applyNormalMatrix(r),i.needsUpdate=!0}let s=this.attributes.tangent;return s!==void 0&&(s.transformDirection(e),s.needsUpdate=!0),this.boundingBox!==null&&this.computeBoundingBox(),this.boundingSphere!==null&&this.computeBoundingSphere(),this._transformed=!0,this}applyQuaternion(e){return bi.makeRotationFromQuaternion(e),this.applyMatrix4(bi),this}rotateX(e){return bi.makeRotationX(e),this.applyMatrix4(bi),this}rotateY(e){return bi.makeRotationY(e),this.applyMatrix4(bi),this}rotateZ(e){return bi.makeRotationZ(e),this.applyMatrix4(bi),this}translate(e,t,i){return bi.makeTranslation(e,t,i),this.applyMatrix4(bi),this}scale(e,t,i){return bi.makeScale(e,t,i),this.applyMatrix4(bi),this}lookAt(e){return _f.lookAt(e),_f.updateMatrix(),this.applyMatrix4(_f.matrix),this}center(){return this.computeBoundingBox(),this.boundingBox.getCenter(_o).negate(),this.translate(_o.x,_o.y,_o.z),this}setFromPoints(e){let t=this.getAttribute("position");if(t===void 0){let i=[];for(let s=0,r=e.length;s<r;s++){let o=e[s];i.push(o.x,o.y,o.z||0)}this.setAttribute("position",new Pn(i,3))}else{let i=Math.min(e.length,t.count);for(let s=0;s<i;s++){let r=e[s];t.setXYZ(s,r.x,r.y,r.z||0)}e.length>t.count&&Je("BufferGeometry: Buffer size too small for points data. Use .dispose() and create a new geometry."),t.needsUpdate=!0}return this}computeBoundingBox(){this.boundingBox===null&&(this.boundingBox=new Js);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){rt("BufferGeometry.computeBoundingBox(): GLBufferAttribute requires a manual bounding box.",this),this.boundingBox.set(new K(-1/0,-1/0,-1/0),new K(1/0,1/0,1/0));return}if(e!==void 0){if(this.boundingBox.setFromBufferAttribute(e),t)for(let i=0,s=t.length;i<s;i++){let r=t[i];ci.setFromBufferAttribute(r),this.morphTargetsRelative?(In.addVectors(this.boundingBox.min,ci.min),this.boundingBox.expandByPoint(In),In.addVectors(this.boundingBox.max,ci.max),this.boundingBox.expandByPoint(In)):(this.boundingBox.expandByPoint(ci.min),this.boundingBox.expandByPoint(ci.max))}}else this.boundingBox.makeEmpty();(isNaN(this.boundingBox.min.x)||isNaN(this.boundingBox.min.y)||isNaN(this.boundingBox.min.z))&&rt('BufferGeometry.computeBoundingBox(): Computed min/max have NaN values. The "position" attribute is likely to have NaN values.',this)}computeBoundingSphere(){this.boundingSphere===null&&(this.boundingSphere=new js);let e=this.attributes.position,t=this.morphAttributes.position;if(e&&e.isGLBufferAttribute){rt("BufferGeometry.computeBoundingSphere(): GLBufferAttribute requires a manual bounding sphere.",this),this.boundingSphere.set(new K,1/0);return}if(e){let i=this.boundingSphere.center;if(ci.setFromBufferAttribute(e),t)for(let r=0,o=t.length;r<o;r++){let a=t[r];ga.setFromBufferAttribute(a),this.morphTargetsRelative?(In.addVectors(ci.min,ga.min),ci.expandByPoint(In),In.addVectors(ci.max,ga.max),ci.expandByPoint(In)):(ci.expandByPoint(ga.min),ci.expandByPoint(ga.max))}ci.getCenter(i);let s=0;for(let r=0,o=e.count;r<o;r++)In.fromBufferAttribute(e,r),s=Math.max(s,i.distanceToSquared(In));if(t)for(let r=0,o=t.length;r<o;r++){let a=t[r],l=this.morphTargetsRelative;for(let c=0,h=a.count;c<h;c++)In.fromBufferAttribute(a,c),l&&(_o.fromBufferAttribute(e,c),In.add(_o)),s=Math.max(s,i.distanceToSquared(In))}this.boundingSphere.radius=Math.sqrt(s),isNaN(this.boundingSphere.radius)&&rt('BufferGeometry.computeBoundingSphere(): Computed radius is NaN. The "position" attribute is likely to have NaN values.',this)}}computeTangents(){let e=this.index,t=this.attributes;if(e===null||t.position===void 0||t.normal===void 0||t.uv===void 0){rt("BufferGeometry: .computeTangents() failed. Missing required attributes (index, position, normal or uv)");return}let i=t.position,s=t.normal,r=t.uv,o=this.getAttribute("tangent");(o===void 0||o.count!==i.count)&&(o=new fi(new Float32Array(4*i.count),4),this.setAttribute("tangent",o));let a=[],l=[],c=new Uint8Array(i.count);for(let k=0;k<i.count;k++)a[k]=new K,l[k]=new K;let h=new K,f=new K,u=new K,p=new ut,g=new ut,S=new ut,d=new K,m=new K;function y(k,U,P){c[k]=c[U]=c[P]=1,h.fromBufferAttribute(i,k),f.fromBufferAttribute(i,U),u.fromBufferAttribute(i,P),p.fromBufferAttribute(r,k),g.fromBufferAttribute(r,U),S.fromBufferAttribute(r,P),f.sub(h),u.sub(h),g.sub(p),S.sub(p);let B=1/(g.x*S.y-S.x*g.y);isFinite(B)&&(d.copy(f).multiplyScalar(S.y).addScaledVector(u,-g.y).multiplyScalar(B),m.copy(u).multiplyScalar(g.x).addScaledVector(f,-S.x).multiplyScalar(B),a[k].add(d),a[U].add(d),a[P].add(d),l[k].add(m),l[U].add(m),l[P].add(m))}let A=this.groups;A.length===0&&(A=[{start:0,count:e.count}]);for(let k=0,U=A.length;k<U;++k){let P=A[k],B=P.start,z=P.count;for(let L=B,H=B+z;L<H;L+=3)y(e.getX(L+0),e.getX(L+1),e.getX(L+2))}let b=new K,C=new K,E=new K,x=new K;function T(k){E.fromBufferAttribute(s,k),x.copy(E);let U=a[k];b.copy(U),b.sub(E.multiplyScalar(E.dot(U))).normalize(),C.crossVectors(x,U);let B=C.dot(l[k])<0?-1:1;o.setXYZW(k,b.x,b.y,b.z,B)}for(let k=0,U=i.count;k<U;++k)c[k]&&T(k);this._transformed=!0}computeVertexNormals(){let e=this.index,t=this.getAttribute("position");if(t!==void 0){let i=this.getAttribute("normal");if(i===void 0||i.count!==t.count)i=new fi(new Float32Array(t.count*3),3),this.setAttribute("normal",i);else for(let u=0,p=i.count;u<p;u++)i.setXYZ(u,0,0,0);let s=new K,r=new K,o=new K,a=new K,l=new K,c=new K,h=new K,f=new K;if(e)for(let u=0,p=e.count;u<p;u+=3){let g=e.getX(u+0),S=e.getX(u+1),d=e.getX(u+2);s.fromBufferAttribute(t,g),r.fromBufferAttribute(t,S),o.fromBufferAttribute(t,d),h.subVectors(o,r),f.subVectors(s,r),h.cross(f),a.fromBufferAttribute(i,g),l.fromBufferAttribute(i,S),c.fromBufferAttribute(i,d),a.add(h),l.add(h),c.add(h),i.setXYZ(g,a.x,a.y,a.z),i.setXYZ(S,l.x,l.y,l.z),i.setXYZ(d,c.x,c.y,c.z)}else for(let u=0,p=t.count;u<p;u+=3)s.fromBufferAttribute(t,u+0),r.fromBufferAttribute(t,u+1),o.fromBufferAttribute(t,u+2),h.subVectors(o,r),f.subVectors(s,r),h.cross(f),i.setXYZ(u+0,h.x,h.y,h.z),i.setXYZ(u+1,h.x,h.y,h.z),i.setXYZ(u+2,h.x,h.y,h.z);this.normalizeNormals(),i.needsUpdate=!0}}normalizeNormals(){let e=this.attributes.normal;for(let t=0,i=e.count;t<i;t++)In.fromBufferAttribute(e,t),In.normalize(),e.setXYZ(t,In.x,In.y,In.z)}toNonIndexed(){function e(a,l){let c=a.array,h=a.itemSize,f=a.normalized,u=new c.constructor(l.length*h),p=0,g=0;for(let S=0,d=l.length;S<d;S++){a.isInterleavedBufferAttribute?p=l[S]*a.data.stride+a.offset:p=l[S]*h;for(let m=0;m<h;m++)u[g++]=c[p++]}return new fi(u,h,f)}if(this.index===null)return Je("BufferGeometry.toNonIndexed(): BufferGeometry is already non-indexed."),this;let t=new n,i=this.index.array,s=this.attributes;for(let a in s){let l=s[a],c=e(l,i);t.setAttribute(a,c)}let r=this.morphAttributes;for(let a in r){let l=[],c=r[a];for(let h=0,f=c.length;h<f;h++){let u=c[h],p=e(u,i);l.push(p)}t.morphAttributes[a]=l}t.morphTargetsRelative=this.morphTargetsRelative;let o=this.groups;for(let a=0,l=o.length;a<l;a++){let c=o[a];t.addGroup(c.start,c.count,c.materialIndex)}return t}toJSON(){let e={metadata:{version:4.7,type:"BufferGeometry",generator:"BufferGeometry.toJSON"}};if(e.uuid=this.uuid,e.type=this.parameters!==void 0&&this._transformed===!0?"BufferGeometry":this.type,e.name=this.name,Object.keys(this.userData).length>0&&(e.userData=this.userData),this.parameters!==void 0&&this._transformed!==!0){let l=this.parameters;for(let c in l)l[c]!==void 0&&(e[c]=l[c]);return e}e.data={attributes:{}};let t=this.index;t!==null&&(e.data.index={type:t.array.constructor.name,array:Array.prototype.slice.call(t.array)});let i=this.attributes;for(let l in i){let c=i[l];e.data.attributes[l]=c.toJSON(e.data)}let s={},r=!1;for(let l in this.morphAttributes){let c=this.morphAttributes[l],h=[];for(let f=0,u=c.length;f<u;f++){let p=c[f];h.push(p.toJSON(e.data))}h.length>0&&(s[l]=h,r=!0)}r&&(e.data.morphAttributes=s,e.data.morphTargetsRelative=this.morphTargetsRelative);let o=this.groups;o.length>0&&(e.data.groups=JSON.parse(JSON.stringify(o)));let a=this.boundingSphere;return a!==null&&(e.data.boundingSphere=a.toJSON()),e}clone(){return new this.constructor().copy(this)}copy(e){this.index=null,this.attributes={},this.morphAttributes={},this.groups=[],this.boundingBox=null,this.boundingSphere=null;let t={};this.name=e.name;let i=e.index;i!==null&&this.setIndex(i.clone());let s=e.attributes;for(let c in s){let h=s[c];this.setAttribute(c,h.clone(t))}let r=e.morphAttributes;for(let c in r){let h=[],f=r[c];for(let u=0,p=f.length;u<p;u++)h.push(f[u].clone(t));this.morphAttributes[c]=h}this.morphTargetsRelative=e.morphTargetsRelative;let o=e.groups;for(let c=0,h=o.length;c<h;c++){let f=o[c];this.addGroup(f.start,f.count,f.materialIndex)}let a=e.boundingBox;a!==null&&(this.boundingBox=a.clone());let l=e.boundingSphere;return l!==null&&(this.boundingSphere=l.clone()),this.drawRange.start=e.drawRange.start,this.drawRange.count=e.drawRange.count,this.userData=e.userData,this._transformed=e._transformed,this}dispose(){this.dispatchEvent({type:"dispose"})}};var xf=new K,Nv=new K,Dv=new ot,ui=class{constructor(e=new K(1,0,0),t=0){this.isPlane=!0,this.normal=e,this.constant=t}set(e,t){return this.normal.copy(e),this.constant=t,this}setComponents(e,t,i,s){return this.normal.set(e,t,i),this.constant=s,this}setFromNormalAndCoplanarPoint(e,t){return this.normal.copy(e),this.constant=-t.dot(this.normal),this}setFromCoplanarPoints(e,t,i){let s=xf.subVectors(i,t).cross(Nv.subVectors(e,t)).normalize();return this.setFromNormalAndCoplanarPoint(s,e),this}copy(e){return this.normal.copy(e.normal),this.constant=e.constant,this}normalize(){let e=1/this.normal.length();return this.normal.multiplyScalar(e),this.constant*=e,this}negate(){return this.constant*=-1,this.normal.negate(),this}distanceToPoint(e){return this.normal.dot(e)+this.constant}distanceToSphere(e){return this.distanceToPoint(e.center)-e.radius}projectPoint(e,t){return t.copy(e).addScaledVector(this.normal,-this.distanceToPoint(e))}intersectLine(e,t,i=!0){let s=e.delta(xf),r=this.normal.dot(s);if(r===0)return this.distanceToPoint(e.start)===0?t.copy(e.start):null;let o=-(e.start.dot(this.normal)+this.constant)/r;return i===!0&&(o<0||o>1)?null:t.copy(e.start).addScaledVector(s,o)}intersectsLine(e){let t=this.distanceToPoint(e.start),i=this.distanceToPoint(e.end);return t<0&&i>0||i<0&&t>0}intersectsBox(e){return e.intersectsPlane(this)}intersectsSphere(e){return e.intersectsPlane(this)}coplanarPoint(e){return e.copy(this.normal).multiplyScalar(-this.constant)}applyMatrix4(e,t){let i=t||Dv.getNormalMatrix(e),s=this.coplanarPoint(xf).applyMatrix4(e),r=this.normal.applyMatrix3(i).normalize();return this.constant=-s.dot(r),this}translate(e){return this.constant-=e.dot(this.normal),this}equals(e){return e.normal.equals(this.normal)&&e.constant===this.constant}clone(){return new this.constructor().copy(this)}toJSON(){return{normal:this.normal.toArray(),constant:this.constant}}fromJSON(e){return this.normal.fromArray(e.normal),this.constant=e.constant,this}},Uv=0,bs=class extends Di{constructor(){super(),this.isMaterial=!0,Object.defineProperty(this,"id",{value:Uv++}),this.uuid=Oo(),this.name="",this.type="Material",this.blending=No,this.side=rr,this.vertexColors=!1,this.opacity=1,this.transparent=!1,this.alphaHash=!1,this.blendSrc=Nf,this.blendDst=Df,this.blendEquation=Cr,this.blendSrcAlpha=null,this.blendDstAlpha=null,this.blendEquationAlpha=null,this.blendColor=new gt(0,0,0),this.blendAlpha=0,this.depthFunc=bo,this.depthTest=!0,this.depthWrite=!0,this.stencilWriteMask=255,this.stencilFunc=p0,this.stencilRef=0,this.stencilFuncMask=255,this.stencilFail=dc,this.stencilZFail=dc,this.stencilZPass=dc,this.stencilWrite=!1,this.clippingPlanes=null,this.clipIntersection=!1,this.clipShadows=!1,this.shadowSide=null,this.colorWrite=!0,this.precision=null,this.polygonOffset=!1,this.polygonOffsetFactor=0,this.polygonOffsetUnits=0,this.dithering=!1,this.alphaToCoverage=!1,this.premultipliedAlpha=!1,this.forceSinglePass=!1,this.allowOverride=!0,this.visible=!0,this.toneMapped=!0,this.userData={},this.version=0,this._alphaTest=0}get alphaTest(){return this._alphaTest}set alphaTest(e){this._alphaTest>0!=e>0&&this.version++,this._alphaTest=e}onBeforeRender(){}onBeforeCompile(){}customProgramCacheKey(){return this.onBeforeCompile.toString()}setValues(e){if(e!==void 0)for(let t in e){let i=e[t];if(i===void 0){Je(`Material: parameter '${t}' has value of undefined.`);continue}let s=this[t];if(s===void 0){Je(`Material: '${t}' is not a property of THREE.${this.type}.`);continue}s&&s.isColor?s.set(i):s&&s.isVector2&&i&&i.isVector2||s&&s.isEuler&&i&&i.isEuler||s&&s.isVector3&&i&&i.isVector3?s.copy(i):this[t]=i}}toJSON(e){let t=e===void 0||typeof e=="string";t&&(e={textures:{},images:{}});let i={metadata:{version:4.7,type:"Material",generator:"Material.toJSON"}};i.uuid=this.uuid,i.type=this.type,i.blending=this.blending,i.side=this.side,i.shadowSide=this.shadowSide,i.vertexColors=this.vertexColors,i.opacity=this.opacity,i.transparent=this.transparent,i.blendSrc=this.blendSrc,i.blendDst=this.blendDst,i.blendEquation=this.blendEquation,i.blendSrcAlpha=this.blendSrcAlpha,i.blendDstAlpha=this.blendDstAlpha,i.blendEquationAlpha=this.blendEquationAlpha,i.blendColor=this.blendColor.getHex(),i.blendAlpha=this.blendAlpha,i.depthFunc=this.depthFunc,i.depthTest=this.depthTest,i.depthWrite=this.depthWrite,i.colorWrite=this.colorWrite,i.clipIntersection=this.clipIntersection,i.clipShadows=this.clipShadows,i.stencilWriteMask=this.stencilWriteMask,i.stencilFunc=this.stencilFunc,i.stencilRef=this.stencilRef,i.stencilFuncMask=this.stencilFuncMask,i.stencilFail=this.stencilFail,i.stencilZFail=this.stencilZFail,i.stencilZPass=this.stencilZPass,i.stencilWrite=this.stencilWrite,i.polygonOffset=this.polygonOffset,i.polygonOffsetFactor=this.polygonOffsetFactor,i.polygonOffsetUnits=this.polygonOffsetUnits,i.dithering=this.dithering,i.alphaTest=this.alphaTest,i.alphaHash=this.alphaHash,i.alphaToCoverage=this.alphaToCoverage,i.premultipliedAlpha=this.premultipliedAlpha,i.forceSinglePass=this.forceSinglePass,i.allowOverride=this.allowOverride,i.visible=this.visible,i.toneMapped=this.toneMapped,i.name=this.name,this.color&&this.color.isColor&&(i.color=this.color.getHex()),this.roughness!==void 0&&(i.roughness=this.roughness),this.metalness!==void 0&&(i.metalness=this.metalness),this.sheen!==void 0&&(i.sheen=this.sheen),this.sheenColor&&this.sheenColor.isColor&&(i.sheenColor=this.sheenColor.getHex()),this.sheenRoughness!==void 0&&(i.sheenRoughness=this.sheenRoughness),this.emissive&&this.emissive.isColor&&(i.emissive=this.emissive.getHex()),this.emissiveIntensity!==void 0&&(i.emissiveIntensity=this.emissiveIntensity),this.specular&&this.specular.isColor&&(i.specular=this.specular.getHex()),this.specularIntensity!==void 0&&(i.specularIntensity=this.specularIntensity),this.specularColor&&this.specularColor.isColor&&(i.specularColor=this.specularColor.getHex()),this.shininess!==void 0&&(i.shininess=this.shininess),this.clearcoat!==void 0&&(i.clearcoat=this.clearcoat),this.clearcoatRoughness!==void 0&&(i.clearcoatRoughness=this.clearcoatRoughness),this.diffuseRoughness!==void 0&&(i.diffuseRoughness=this.diffuseRoughness),this.diffuseRoughnessMap&&this.diffuseRoughnessMap.isTexture&&(i.diffuseRoughnessMap=this.diffuseRoughnessMap.toJSON(e).uuid),this.clearcoatMap&&this.clearcoatMap.isTexture&&(i.clearcoatMap=this.clearcoatMap.toJSON(e).uuid),this.clearcoatRoughnessMap&&this.clearcoatRoughnessMap.isTexture&&(i.clearcoatRoughnessMap=this.clearcoatRoughnessMap.toJSON(e).uuid),this.clearcoatNormalMap&&this.clearcoatNormalMap.isTexture&&(i.clearcoatNormalMap=this.clearcoatNormalMap.toJSON(e).uuid,i.clearcoatNormalScale=this.clearcoatNormalScale.toArray()),this.sheenColorMap&&this.sheenColorMap.isTexture&&(i.sheenColorMap=this.sheenColorMap.toJSON(e).uuid),this.sheenRoughnessMap&&this.sheenRoughnessMap.isTexture&&(i.sheenRoughnessMap=this.sheenRoughnessMap.toJSON(e).uuid),this.dispersion!==void 0&&(i.dispersion=this.dispersion),this.retroreflectivity!==void 0&&(i.retroreflectivity=this.retroreflectivity),this.iridescence!==void 0&&(i.iridescence=this.iridescence),this.iridescenceIOR!==void 0&&(i.iridescenceIOR=this.iridescenceIOR),this.iridescenceThicknessMinimum!==void 0&&(i.iridescenceThicknessMinimum=this.iridescenceThicknessMinimum),this.iridescenceThicknessMaximum!==void 0&&(i.iridescenceThicknessMaximum=this.iridescenceThicknessMaximum),this.iridescenceMap&&this.iridescenceMap.isTexture&&(i.iridescenceMap=this.iridescenceMap.toJSON(e).uuid),this.iridescenceThicknessMap&&this.iridescenceThicknessMap.isTexture&&(i.iridescenceThicknessMap=this.iridescenceThicknessMap.toJSON(e).uuid),this.anisotropy!==void 0&&(i.anisotropy=this.anisotropy),this.anisotropyRotation!==void 0&&(i.anisotropyRotation=this.anisotropyRotation),this.anisotropyMap&&this.anisotropyMap.isTexture&&(i.anisotropyMap=this.anisotropyMap.toJSON(e).uuid),this.map&&this.map.isTexture&&(i.map=this.map.toJSON(e).uuid),this.matcap&&this.matcap.isTexture&&(i.matcap=this.matcap.toJSON(e).uuid),this.alphaMap&&this.alphaMap.isTexture&&(i.alphaMap=this.alphaMap.toJSON(e).uuid),this.lightMap&&this.lightMap.isTexture&&(i.lightMap=this.lightMap.toJSON(e).uuid,i.lightMapIntensity=this.lightMapIntensity),this.aoMap&&this.aoMap.isTexture&&(i.aoMap=this.aoMap.toJSON(e).uuid,i.aoMapIntensity=this.aoMapIntensity),this.bumpMap&&this.bumpMap.isTexture&&(i.bumpMap=this.bumpMap.toJSON(e).uuid,i.bumpScale=this.bumpScale),this.normalMap&&this.normalMap.isTexture&&(i.normalMap=this.normalMap.toJSON(e).uuid,i.normalMapType=this.normalMapType,i.normalScale=this.normalScale.toArray()),this.displacementMap&&this.displacementMap.isTexture&&(i.displacementMap=this.displacementMap.toJSON(e).uuid,i.displacementScale=this.displacementScale,i.displacementBias=this.displacementBias),this.roughnessMap&&this.roughnessMap.isTexture&&(i.roughnessMap=this.roughnessMap.toJSON(e).uuid),this.metalnessMap&&this.metalnessMap.isTexture&&(i.metalnessMap=this.metalnessMap.toJSON(e).uuid),this.emissiveMap&&this.emissiveMap.isTexture&&(i.emissiveMap=this.emissiveMap.toJSON(e).uuid),this.specularMap&&this.specularMap.isTexture&&(i.specularMap=this.specularMap.toJSON(e).uuid),this.specularIntensityMap&&this.specularIntensityMap.isTexture&&(i.specularIntensityMap=this.specularIntensityMap.toJSON(e).uuid),this.specularColorMap&&this.specularColorMap.isTexture&&(i.specularColorMap=this.specularColorMap.toJSON(e).uuid),this.envMap&&this.envMap.isTexture&&(i.envMap=this.envMap.toJSON(e).uuid,this.combine!==void 0&&(i.combine=this.combine)),this.envMapRotation!==void 0&&(i.envMapRotation=this.envMapRotation.toArray()),this.envMapIntensity!==void 0&&(i.envMapIntensity=this.envMapIntensity),this.reflectivity!==void 0&&(i.reflectivity=this.reflectivity),this.refractionRatio!==void 0&&(i.refractionRatio=this.refractionRatio),this.gradientMap&&this.gradientMap.isTexture&&(i.gradientMap=this.gradientMap.toJSON(e).uuid),this.transmission!==void 0&&(i.transmission=this.transmission),this.transmissionMap&&this.transmissionMap.isTexture&&(i.transmissionMap=this.transmissionMap.toJSON(e).uuid),this.thickness!==void 0&&(i.thickness=this.thickness),this.thicknessMap&&this.thicknessMap.isTexture&&(i.thicknessMap=this.thicknessMap.toJSON(e).uuid),this.attenuationDistance!==void 0&&(i.attenuationDistance=this.attenuationDistance),this.attenuationColor!==void 0&&(i.attenuationColor=this.attenuationColor.getHex()),this.size!==void 0&&(i.size=this.size),this.sizeAttenuation!==void 0&&(i.sizeAttenuation=this.sizeAttenuation),Array.isArray(this.clippingPlanes)&&this.clippingPlanes.length>0&&(i.clippingPlanes=this.clippingPlanes.map(r=>r.toJSON())),this.rotation!==void 0&&(i.rotation=this.rotation),this.depthPacking!==void 0&&(i.depthPacking=this.depthPacking),this.linewidth!==void 0&&(i.linewidth=this.linewidth),this.linecap!==void 0&&(i.linecap=this.linecap),this.linejoin!==void 0&&(i.linejoin=this.linejoin),this.dashSize!==void 0&&(i.dashSize=this.dashSize),this.gapSize!==void 0&&(i.gapSize=this.gapSize),this.scale!==void 0&&(i.scale=this.scale),this.wireframe!==void 0&&(i.wireframe=this.wireframe),this.wireframeLinewidth!==void 0&&(i.wireframeLinewidth=this.wireframeLinewidth),this.wireframeLinecap!==void 0&&(i.wireframeLinecap=this.wireframeLinecap),this.wireframeLinejoin!==void 0&&(i.wireframeLinejoin=this.wireframeLinejoin),this.flatShading!==void 0&&(i.flatShading=this.flatShading),this.fog!==void 0&&(i.fog=this.fog),Object.keys(this.userData).length>0&&(i.userData=this.userData);function s(r){let o=[];for(let a in r){let l=r[a];delete l.metadata,o.push(l)}return o}if(t){let r=s(e.textures),o=s(e.images);r.length>0&&(i.textures=r),o.length>0&&(i.images=o)}return i}fromJSON(e,t){if(e.uuid!==void 0&&(this.uuid=e.uuid),e.name!==void 0&&(this.name=e.name),e.color!==void 0&&this.color!==void 0&&this.color.setHex(e.color),e.roughness!==void 0&&(this.roughness=e.roughness),e.metalness!==void 0&&(this.metalness=e.metalness),e.sheen!==void 0&&(this.sheen=e.sheen),e.sheenColor!==void 0&&(this.sheenColor=new gt().setHex(e.sheenColor)),e.sheenRoughness!==void 0&&(this.sheenRoughness=e.sheenRoughness),e.emissive!==void 0&&this.emissive!==void 0&&this.emissive.setHex(e.emissive),e.specular!==void 0&&this.specular!==void 0&&this.specular.setHex(e.specular),e.specularIntensity!==void 0&&(this.specularIntensity=e.specularIntensity),e.specularColor!==void 0&&this.specularColor!==void 0&&this.specularColor.setHex(e.specularColor),e.shininess!==void 0&&(this.shininess=e.shininess),e.clearcoat!==void 0&&(this.clearcoat=e.clearcoat),e.clearcoatRoughness!==void 0&&(this.clearcoatRoughness=e.clearcoatRoughness),e.diffuseRoughness!==void 0&&(this.diffuseRoughness=e.diffuseRoughness),e.dispersion!==void 0&&(this.dispersion=e.dispersion),e.retroreflectivity!==void 0&&(this.retroreflectivity=e.retroreflectivity),e.iridescence!==void 0&&(this.iridescence=e.iridescence),e.iridescenceIOR!==void 0&&(this.iridescenceIOR=e.iridescenceIOR),e.iridescenceThicknessMinimum!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessMinimum),e.iridescenceThicknessMaximum!==void 0&&(this.iridescenceThicknessMaximum=e.iridescenceThicknessMaximum),e.iridescenceThicknessRange!==void 0&&(this.iridescenceThicknessMinimum=e.iridescenceThicknessRange[0],this.iridescenceThicknessMaximum=e.iridescenceThicknessRange[1]),e.transmission!==void 0&&(this.transmission=e.transmission),e.thickness!==void 0&&(this.thickness=e.thickness),e.attenuationDistance!==void 0&&(this.attenuationDistance=e.attenuationDistance),e.attenuationColor!==void 0&&this.attenuationColor!==void 0&&this.attenuationColor.setHex(e.attenuationColor),e.anisotropy!==void 0&&(this.anisotropy=e.anisotropy),e.anisotropyRotation!==void 0&&(this.anisotropyRotation=e.anisotropyRotation),e.fog!==void 0&&(this.fog=e.fog),e.flatShading!==void 0&&(this.flatShading=e.flatShading),e.blending!==void 0&&(this.blending=e.blending),e.combine!==void 0&&(this.combine=e.combine),e.side!==void 0&&(this.side=e.side),e.shadowSide!==void 0&&(this.shadowSide=e.shadowSide),e.opacity!==void 0&&(this.opacity=e.opacity),e.transparent!==void 0&&(this.transparent=e.transparent),e.alphaTest!==void 0&&(this.alphaTest=e.alphaTest),e.alphaHash!==void 0&&(this.alphaHash=e.alphaHash),e.depthFunc!==void 0&&(this.depthFunc=e.depthFunc),e.depthTest!==void 0&&(this.depthTest=e.depthTest),e.depthWrite!==void 0&&(this.depthWrite=e.depthWrite),e.colorWrite!==void 0&&(this.colorWrite=e.colorWrite),e.clippingPlanes!==void 0&&(this.clippingPlanes=e.clippingPlanes.map(i=>new ui().fromJSON(i))),e.clipIntersection!==void 0&&(this.clipIntersection=e.clipIntersection),e.clipShadows!==void 0&&(this.clipShadows=e.clipShadows),e.depthPacking!==void 0&&(this.depthPacking=e.depthPacking),e.blendSrc!==void 0&&(this.blendSrc=e.blendSrc),e.blendDst!==void 0&&(this.blendDst=e.blendDst),e.blendEquation!==void 0&&(this.blendEquation=e.blendEquation),e.blendSrcAlpha!==void 0&&(this.blendSrcAlpha=e.blendSrcAlpha),e.blendDstAlpha!==void 0&&(this.blendDstAlpha=e.blendDstAlpha),e.blendEquationAlpha!==void 0&&(this.blendEquationAlpha=e.blendEquationAlpha),e.blendColor!==void 0&&this.blendColor!==void 0&&this.blendColor.setHex(e.blendColor),e.blendAlpha!==void 0&&(this.blendAlpha=e.blendAlpha),e.stencilWriteMask!==void 0&&(this.stencilWriteMask=e.stencilWriteMask),e.stencilFunc!==void 0&&(this.stencilFunc=e.stencilFunc),e.stencilRef!==void 0&&(this.stencilRef=e.stencilRef),e.stencilFuncMask!==void 0&&(this.stencilFuncMask=e.stencilFuncMask),e.stencilFail!==void 0&&(this.stencilFail=e.stencilFail),e.stencilZFail!==void 0&&(this.stencilZFail=e.stencilZFail),e.stencilZPass!==void 0&&(this.stencilZPass=e.stencilZPass),e.stencilWrite!==void 0&&(this.stencilWrite=e.stencilWrite),e.wireframe!==void 0&&(this.wireframe=e.wireframe),e.wireframeLinewidth!==void 0&&(this.wireframeLinewidth=e.wireframeLinewidth),e.wireframeLinecap!==void 0&&(this.wireframeLinecap=e.wireframeLinecap),e.wireframeLinejoin!==void 0&&(this.wireframeLinejoin=e.wireframeLinejoin),e.rotation!==void 0&&(this.rotation=e.rotation),e.linewidth!==void 0&&(this.linewidth=e.linewidth),e.linecap!==void 0&&(this.linecap=e.linecap),e.linejoin!==void 0&&(this.linejoin=e.linejoin),e.dashSize!==void 0&&(this.dashSize=e.dashSize),e.gapSize!==void 0&&(this.gapSize=e.gapSize),e.scale!==void 0&&(this.scale=e.scale),e.polygonOffset!==void 0&&(this.polygonOffset=e.polygonOffset),e.polygonOffsetFactor!==void 0&&(this.polygonOffsetFactor=e.polygonOffsetFactor),e.polygonOffsetUnits!==void 0&&(this.polygonOffsetUnits=e.polygonOffsetUnits),e.dithering!==void 0&&(this.dithering=e.dithering),e.alphaToCoverage!==void 0&&(this.alphaToCoverage=e.alphaToCoverage),e.premultipliedAlpha!==void 0&&(this.premultipliedAlpha=e.premultipliedAlpha),e.forceSinglePass!==void 0&&(this.forceSinglePass=e.forceSinglePass),e.allowOverride!==void 0&&(this.allowOverride=e.allowOverride),e.visible!==void 0&&(this.visible=e.visible),e.toneMapped!==void 0&&(this.toneMapped=e.toneMapped),e.userData!==void 0&&(this.userData=e.userData),e.vertexColors!==void 0&&(typeof e.vertexColors=="number"?this.vertexColors=e.vertexColors>0:this.vertexColors=e.vertexColors),e.size!==void 0&&(this.size=e.size),e.sizeAttenuation!==void 0&&(this.sizeAttenuation=e.sizeAttenuation),e.map!==void 0&&(this.map=t[e.map]||null),e.matcap!==void 0&&(this.matcap=t[e.matcap]||null),e.alphaMap!==void 0&&(this.alphaMap=t[e.alphaMap]||null),e.bumpMap!==void 0&&(this.bumpMap=t[e.bumpMap]||null),e.bumpScale!==void 0&&(this.bumpScale=e.bumpScale),e.normalMap!==void 0&&(this.normalMap=t[e.normalMap]||null),e.normalMapType!==void 0&&(this.normalMapType=e.normalMapType),e.normalScale!==void 0){let i=e.normalScale;Array.isArray(i)===!1&&(i=[i,i]),this.normalScale=new ut().fromArray(i)}return e.displacementMap!==void 0&&(this.displacementMap=t[e.displacementMap]||null),e.displacementScale!==void 0&&(this.displacementScale=e.displacementScale),e.displacementBias!==void 0&&(this.displacementBias=e.displacementBias),e.roughnessMap!==void 0&&(this.roughnessMap=t[e.roughnessMap]||null),e.metalnessMap!==void 0&&(this.metalnessMap=t[e.metalnessMap]||null),e.emissiveMap!==void 0&&(this.emissiveMap=t[e.emissiveMap]||null),e.emissiveIntensity!==void 0&&(this.emissiveIntensity=e.emissiveIntensity),e.specularMap!==void 0&&(this.specularMap=t[e.specularMap]||null),e.specularIntensityMap!==void 0&&(this.specularIntensityMap=t[e.specularIntensityMap]||null),e.specularColorMap!==void 0&&(this.specularColorMap=t[e.specularColorMap]||null),e.envMap!==void 0&&(this.envMap=t[e.envMap]||null),e.envMapRotation!==void 0&&this.envMapRotation.fromArray(e.envMapRotation),e.envMapIntensity!==void 0&&(this.envMapIntensity=e.envMapIntensity),e.reflectivity!==void 0&&(this.reflectivity=e.reflectivity),e.refractionRatio!==void 0&&(this.refractionRatio=e.refractionRatio),e.lightMap!==void 0&&(this.lightMap=t[e.lightMap]||null),e.lightMapIntensity!==void 0&&(this.lightMapIntensity=e.lightMapIntensity),e.aoMap!==void 0&&(this.aoMap=t[e.aoMap]||null),e.aoMapIntensity!==void 0&&(this.aoMapIntensity=e.aoMapIntensity),e.gradientMap!==void 0&&(this.gradientMap=t[e.gradientMap]||null),e.clearcoatMap!==void 0&&(this.clearcoatMap=t[e.clearcoatMap]||null),e.clearcoatRoughnessMap!==void 0&&(this.clearcoatRoughnessMap=t[e.clearcoatRoughnessMap]||null),e.clearcoatNormalMap!==void 0&&(this.clearcoatNormalMap=t[e.clearcoatNormalMap]||null),e.clearcoatNormalScale!==void 0&&(this.clearcoatNormalScale=new ut().fromArray(e.clearcoatNormalScale)),e.diffuseRoughnessMap!==void 0&&(this.diffuseRoughnessMap=t[e.diffuseRoughnessMap]||null),e.iridescenceMap!==void 0&&(this.iridescenceMap=t[e.iridescenceMap]||null),e.iridescenceThicknessMap!==void 0&&(this.iridescenceThicknessMap=t[e.iridescenceThicknessMap]||null),e.transmissionMap!==void 0&&(this.transmissionMap=t[e.transmissionMap]||null),e.thicknessMap!==void 0&&(this.thicknessMap=t[e.thicknessMap]||null),e.anisotropyMap!==void 0&&(this.anisotropyMap=t[e.anisotropyMap]||null),e.sheenColorMap!==void 0&&(this.sheenColorMap=t[e.sheenColorMap]||null),e.sheenRoughnessMap!==void 0&&(this.sheenRoughnessMap=t[e.sheenRoughnessMap]||null),this}clone(){return new this.constructor().copy(this)}copy(e){this.name=e.name,this.blending=e.blending,this.side=e.side,this.vertexColors=e.vertexColors,this.opacity=e.opacity,this.transparent=e.transparent,this.blendSrc=e.blendSrc,this.blendDst=e.blendDst,this.blendEquation=e.blendEquation,this.blendSrcAlpha=e.blendSrcAlpha,this.blendDstAlpha=e.blendDstAlpha,this.blendEquationAlpha=e.blendEquationAlpha,this.blendColor.copy(e.blendColor),this.blendAlpha=e.blendAlpha,this.depthFunc=e.depthFunc,this.depthTest=e.depthTest,this.depthWrite=e.depthWrite,this.stencilWriteMask=e.stencilWriteMask,this.stencilFunc=e.stencilFunc,this.stencilRef=e.stencilRef,this.stencilFuncMask=e.stencilFuncMask,this.stencilFail=e.stencilFail,this.stencilZFail=e.stencilZFail,this.stencilZPass=e.stencilZPass,this.stencilWrite=e.stencilWrite;let t=e.clippingPlanes,i=null;if(t!==null){let s=t.length;i=new Array(s);for(let r=0;r!==s;++r)i[r]=t[r].clone()}return this.clippingPlanes=i,this.clipIntersection=e.clipIntersection,this.clipShadows=e.clipShadows,this.shadowSide=e.shadowSide,this.colorWrite=e.colorWrite,this.precision=e.precision,this.polygonOffset=e.polygonOffset,this.polygonOffsetFactor=e.polygonOffsetFactor,this.polygonOffsetUnits=e.polygonOffsetUnits,this.dithering=e.dithering,this.alphaTest=e.alphaTest,this.alphaHash=e.alphaHash,this.alphaToCoverage=e.alphaToCoverage,this.premultipliedAlpha=e.premultipliedAlpha,this.forceSinglePass=e.forceSinglePass,this.allowOverride=e.allowOverride,this.visible=e.visible,this.toneMapped=e.toneMapped,this.userData=JSON.parse(JSON.stringify(e.userData)),this}dispose(){this.dispatchEvent({type:"dispose"})}set needsUpdate(e){e===!0&&this.version++}};var ys=new K,yf=new K,Zl=new K,Kl=new K,Qs=class{constructor(e=new K,t=new K(0,0,-1)){this.origin=e,this.direction=t}set(e,t){return this.origin.copy(e),this.direction.copy(t),this}copy(e){return this.origin.copy(e.origin),this.direction.copy(e.direction),this}at(e,t){return t.copy(this.origin).addScaledVector(this.direction,e)}lookAt(e){return this.direction.copy(e).sub(this.origin).normalize(),this}recast(e){return this.origin.copy(this.at(e,ys)),this}closestPointToPoint(e,t){t.subVectors(e,this.origin);let i=t.dot(this.direction);return i<0?t.copy(this.origin):t.copy(this.origin).addScaledVector(this.direction,i)}distanceToPoint(e){return Math.sqrt(this.distanceSqToPoint(e))}distanceSqToPoint(e){let t=ys.subVectors(e,this.origin).dot(this.direction);return t<0?this.origin.distanceToSquared(e):(ys.copy(this.origin).addScaledVector(this.direction,t),ys.distanceToSquared(e))}distanceSqToSegment(e,t,i,s){yf.copy(e).add(t).multiplyScalar(.5),Zl.copy(t).sub(e).normalize(),Kl.copy(this.origin).sub(yf);let r=e.distanceTo(t)*.5,o=-this.direction.dot(Zl),a=Kl.dot(this.direction),l=-Kl.dot(Zl),c=Kl.lengthSq(),h=Math.abs(1-o*o),f,u,p,g;if(h>0)if(f=o*l-a,u=o*a-l,g=r*h,f>=0)if(u>=-g)if(u<=g){let S=1/h;f*=S,u*=S,p=f*(f+o*u+2*a)+u*(o*f+u+2*l)+c}else u=r,f=Math.max(0,-(o*u+a)),p=-f*f+u*(u+2*l)+c;else u=-r,f=Math.max(0,-(o*u+a)),p=-f*f+u*(u+2*l)+c;else u<=-g?(f=Math.max(0,-(-o*r+a)),u=f>0?-r:Math.min(Math.max(-r,-l),r),p=-f*f+u*(u+2*l)+c):u<=g?(f=0,u=Math.min(Math.max(-r,-l),r),p=u*(u+2*l)+c):(f=Math.max(0,-(o*r+a)),u=f>0?r:Math.min(Math.max(-r,-l),r),p=-f*f+u*(u+2*l)+c);else u=o>0?-r:r,f=Math.max(0,-(o*u+a)),p=-f*f+u*(u+2*l)+c;return i&&i.copy(this.origin).addScaledVector(this.direction,f),s&&s.copy(yf).addScaledVector(Zl,u),p}intersectSphere(e,t){if(e.radius<0)return null;ys.subVectors(e.center,this.origin);let i=ys.dot(this.direction),s=ys.dot(ys)-i*i,r=e.radius*e.radius;if(s>r)return null;let o=Math.sqrt(r-s),a=i-o,l=i+o;return l<0?null:a<0?this.at(l,t):this.at(a,t)}intersectsSphere(e){return e.radius<0?!1:this.distanceSqToPoint(e.center)<=e.radius*e.radius}distanceToPlane(e){let t=e.normal.dot(this.direction);if(t===0)return e.distanceToPoint(this.origin)===0?0:null;let i=-(this.origin.dot(e.normal)+e.constant)/t;return i>=0?i:null}intersectPlane(e,t){let i=this.distanceToPlane(e);return i===null?null:this.at(i,t)}intersectsPlane(e){let t=e.distanceToPoint(this.origin);return t===0||e.normal.dot(this.direction)*t<0}intersectBox(e,t){let i,s,r,o,a,l,c=1/this.direction.x,h=1/this.direction.y,f=1/this.direction.z,u=this.origin;return c>=0?(i=(e.min.x-u.x)*c,s=(e.max.x-u.x)*c):(i=(e.max.x-u.x)*c,s=(e.min.x-u.x)*c),h>=0?(r=(e.min.y-u.y)*h,o=(e.max.y-u.y)*h):(r=(e.max.y-u.y)*h,o=(e.min.y-u.y)*h),i>o||r>s||((r>i||isNaN(i))&&(i=r),(o<s||isNaN(s))&&(s=o),f>=0?(a=(e.min.z-u.z)*f,l=(e.max.z-u.z)*f):(a=(e.max.z-u.z)*f,l=(e.min.z-u.z)*f),i>l||a>s)||((a>i||i!==i)&&(i=a),(l<s||s!==s)&&(s=l),s<0)?null:this.at(i>=0?i:s,t)}intersectsBox(e){return this.intersectBox(e,ys)!==null}intersectTriangle(e,t,i,s,r){let o=this.origin,a=this.direction,l=a.x,c=a.y,h=a.z,f=e.x-o.x,u=e.y-o.y,p=e.z-o.z,g=t.x-o.x,S=t.y-o.y,d=t.z-o.z,m=i.x-o.x,y=i.y-o.y,A=i.z-o.z,b=Math.abs(l),C=Math.abs(c),E=Math.abs(h),x,T,k,U,P,B,z,L,H,W,D,te;if(b>=C&&b>=E?(k=l,B=f,H=g,te=m,l>=0?(x=c,T=h,U=u,P=p,z=S,L=d,W=y,D=A):(x=h,T=c,U=p,P=u,z=d,L=S,W=A,D=y)):C>=E?(k=c,B=u,H=S,te=y,c>=0?(x=h,T=l,U=p,P=f,z=d,L=g,W=A,D=m):(x=l,T=h,U=f,P=p,z=g,L=d,W=m,D=A)):(k=h,B=p,H=d,te=A,h>=0?(x=l,T=c,U=f,P=u,z=g,L=S,W=m,D=y):(x=c,T=l,U=u,P=f,z=S,L=g,W=y,D=m)),k===0)return null;let X=x/k,q=T/k,j=1/k,ae=U-X*B,ce=P-q*B,ee=z-X*H,pe=L-q*H,fe=W-X*te,Me=D-q*te,ye=fe*pe-Me*ee,qe=ae*Me-ce*fe,it=ee*ce-pe*ae;if(s){if(ye<0||qe<0||it<0)return null}else if((ye<0||qe<0||it<0)&&(ye>0||qe>0||it>0))return null;let We=ye+qe+it;if(We===0)return null;let Ce=j*(ye*B+qe*H+it*te);return(We>0?Ce<0:Ce>0)?null:this.at(Ce/We,r)}applyMatrix4(e){return this.origin.applyMatrix4(e),this.direction.transformDirection(e),this}equals(e){return e.origin.equals(this.origin)&&e.direction.equals(this.direction)}clone(){return new this.constructor().copy(this)}},Ac=class extends bs{constructor(e){super(),this.isMeshBasicMaterial=!0,this.type="MeshBasicMaterial",this.color=new gt(16777215),this.map=null,this.lightMap=null,this.lightMapIntensity=1,this.aoMap=null,this.aoMapIntensity=1,this.specularMap=null,this.alphaMap=null,this.envMap=null,this.envMapRotation=new Ks,this.combine=Uf,this.reflectivity=1,this.refractionRatio=.98,this.wireframe=!1,this.wireframeLinewidth=1,this.wireframeLinecap="round",this.wireframeLinejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.lightMap=e.lightMap,this.lightMapIntensity=e.lightMapIntensity,this.aoMap=e.aoMap,this.aoMapIntensity=e.aoMapIntensity,this.specularMap=e.specularMap,this.alphaMap=e.alphaMap,this.envMap=e.envMap,this.envMapRotation.copy(e.envMapRotation),this.combine=e.combine,this.reflectivity=e.reflectivity,this.refractionRatio=e.refractionRatio,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.wireframeLinecap=e.wireframeLinecap,this.wireframeLinejoin=e.wireframeLinejoin,this.fog=e.fog,this}},Ag=new en,wr=new Qs,Jl=new js,Rg=new K,jl=new K,Ql=new K,ec=new K,vf=new K,tc=new K,Cg=new K,nc=new K,ji=class extends Jn{constructor(e=new jn,t=new Ac){super(),this.isMesh=!0,this.type="Mesh",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.count=1,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}getVertexPosition(e,t){let i=this.geometry,s=i.attributes.position,r=i.morphAttributes.position,o=i.morphTargetsRelative;t.fromBufferAttribute(s,e);let a=this.morphTargetInfluences;if(r&&a){tc.set(0,0,0);for(let l=0,c=r.length;l<c;l++){let h=a[l],f=r[l];h!==0&&(vf.fromBufferAttribute(f,e),o?tc.addScaledVector(vf,h):tc.addScaledVector(vf.sub(t),h))}t.add(tc)}return t}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,s=this.material,r=this.matrixWorld;s!==void 0&&(i.boundingSphere===null&&i.computeBoundingSphere(),Jl.copy(i.boundingSphere),Jl.applyMatrix4(r),wr.copy(e.ray).recast(e.near),!(Jl.containsPoint(wr.origin)===!1&&(wr.intersectSphere(Jl,Rg)===null||wr.origin.distanceToSquared(Rg)>(e.far-e.near)**2))&&(Ag.copy(r).invert(),wr.copy(e.ray).applyMatrix4(Ag),!(i.boundingBox!==null&&wr.intersectsBox(i.boundingBox)===!1)&&this._computeIntersections(e,t,wr)))}_computeIntersections(e,t,i){let s,r=this.geometry,o=this.material,a=r.index,l=r.attributes.position,c=r.attributes.uv,h=r.attributes.uv1,f=r.attributes.normal,u=r.groups,p=r.drawRange;if(a!==null)if(Array.isArray(o))for(let g=0,S=u.length;g<S;g++){let d=u[g],m=o[d.materialIndex],y=Math.max(d.start,p.start),A=Math.min(a.count,Math.min(d.start+d.count,p.start+p.count));for(let b=y,C=A;b<C;b+=3){let E=a.getX(b),x=a.getX(b+1),T=a.getX(b+2);s=ic(this,m,e,i,c,h,f,E,x,T),s&&(s.faceIndex=Math.floor(b/3),s.face.materialIndex=d.materialIndex,t.push(s))}}else{let g=Math.max(0,p.start),S=Math.min(a.count,p.start+p.count);for(let d=g,m=S;d<m;d+=3){let y=a.getX(d),A=a.getX(d+1),b=a.getX(d+2);s=ic(this,o,e,i,c,h,f,y,A,b),s&&(s.faceIndex=Math.floor(d/3),t.push(s))}}else if(l!==void 0)if(Array.isArray(o))for(let g=0,S=u.length;g<S;g++){let d=u[g],m=o[d.materialIndex],y=Math.max(d.start,p.start),A=Math.min(l.count,Math.min(d.start+d.count,p.start+p.count));for(let b=y,C=A;b<C;b+=3){let E=b,x=b+1,T=b+2;s=ic(this,m,e,i,c,h,f,E,x,T),s&&(s.faceIndex=Math.floor(b/3),s.face.materialIndex=d.materialIndex,t.push(s))}}else{let g=Math.max(0,p.start),S=Math.min(l.count,p.start+p.count);for(let d=g,m=S;d<m;d+=3){let y=d,A=d+1,b=d+2;s=ic(this,o,e,i,c,h,f,y,A,b),s&&(s.faceIndex=Math.floor(d/3),t.push(s))}}}};function Ov(n,e,t,i,s,r,o,a){let l;if(e.side===$n?l=i.intersectTriangle(o,r,s,!0,a):l=i.intersectTriangle(s,r,o,e.side===rr,a),l===null)return null;nc.copy(a),nc.applyMatrix4(n.matrixWorld);let c=t.ray.origin.distanceTo(nc);return c<t.near||c>t.far?null:{distance:c,point:nc.clone(),object:n}}function ic(n,e,t,i,s,r,o,a,l,c){n.getVertexPosition(a,jl),n.getVertexPosition(l,Ql),n.getVertexPosition(c,ec);let h=Ov(n,e,t,i,jl,Ql,ec,Cg);if(h){let f=new K;Zs.getBarycoord(Cg,jl,Ql,ec,f),s&&(h.uv=Zs.getInterpolatedAttribute(s,a,l,c,f,new ut)),r&&(h.uv1=Zs.getInterpolatedAttribute(r,a,l,c,f,new ut)),o&&(h.normal=Zs.getInterpolatedAttribute(o,a,l,c,f,new K),h.normal.dot(i.direction)>0&&h.normal.multiplyScalar(-1));let u={a,b:l,c,normal:new K,materialIndex:0};Zs.getNormal(jl,Ql,ec,u.normal),h.face=u,h.barycoord=f}return h}var Rc=class extends Kn{constructor(e=null,t=1,i=1,s,r,o,a,l,c=Ln,h=Ln,f,u){super(null,o,a,l,c,h,s,r,f,u),this.isDataTexture=!0,this.image={data:e,width:t,height:i},this.generateMipmaps=!1,this.flipY=!1,this.unpackAlignment=1}};var Er=new js,Fv=new ut(.5,.5),sc=new K,Ar=class{constructor(e=new ui,t=new ui,i=new ui,s=new ui,r=new ui,o=new ui){this.planes=[e,t,i,s,r,o]}set(e,t,i,s,r,o){let a=this.planes;return a[0].copy(e),a[1].copy(t),a[2].copy(i),a[3].copy(s),a[4].copy(r),a[5].copy(o),this}copy(e){let t=this.planes;for(let i=0;i<6;i++)t[i].copy(e.planes[i]);return this}setFromProjectionMatrix(e,t=Mi,i=!1){let s=this.planes,r=e.elements,o=r[0],a=r[1],l=r[2],c=r[3],h=r[4],f=r[5],u=r[6],p=r[7],g=r[8],S=r[9],d=r[10],m=r[11],y=r[12],A=r[13],b=r[14],C=r[15];if(s[0].setComponents(c-o,p-h,m-g,C-y).normalize(),s[1].setComponents(c+o,p+h,m+g,C+y).normalize(),s[2].setComponents(c+a,p+f,m+S,C+A).normalize(),s[3].setComponents(c-a,p-f,m-S,C-A).normalize(),i)s[4].setComponents(l,u,d,b).normalize(),s[5].setComponents(c-l,p-u,m-d,C-b).normalize();else if(s[4].setComponents(c-l,p-u,m-d,C-b).normalize(),t===Mi)s[5].setComponents(c+l,p+u,m+d,C+b).normalize();else if(t===wa)s[5].setComponents(l,u,d,b).normalize();else throw new Error("THREE.Frustum.setFromProjectionMatrix(): Invalid coordinate system: "+t);return this}intersectsObject(e){if(e.boundingSphere!==void 0)e.boundingSphere===null&&e.computeBoundingSphere(),Er.copy(e.boundingSphere).applyMatrix4(e.matrixWorld);else{let t=e.geometry;t.boundingSphere===null&&t.computeBoundingSphere(),Er.copy(t.boundingSphere).applyMatrix4(e.matrixWorld)}return this.intersectsSphere(Er)}intersectsSprite(e){Er.center.set(0,0,0);let t=Fv.distanceTo(e.center);return Er.radius=.7071067811865476+t,Er.applyMatrix4(e.matrixWorld),this.intersectsSphere(Er)}intersectsSphere(e){let t=this.planes,i=e.center,s=-e.radius;for(let r=0;r<6;r++)if(t[r].distanceToPoint(i)<s)return!1;return!0}intersectsBox(e){let t=this.planes;for(let i=0;i<6;i++){let s=t[i];if(sc.x=s.normal.x>0?e.max.x:e.min.x,sc.y=s.normal.y>0?e.max.y:e.min.y,sc.z=s.normal.z>0?e.max.z:e.min.z,s.distanceToPoint(sc)<0)return!1}return!0}containsPoint(e){let t=this.planes;for(let i=0;i<6;i++)if(t[i].distanceToPoint(e)<0)return!1;return!0}clone(){return new this.constructor().copy(this)}},Ig=new en,Cc=class n{constructor(){this.coordinateSystem=Mi,this._frustums=[],this._count=0}setFromArrayCamera(e){let t=e.cameras,i=this._frustums;for(let s=0;s<t.length;s++){let r=t[s];Ig.multiplyMatrices(r.projectionMatrix,r.matrixWorldInverse),i[s]===void 0&&(i[s]=new Ar),i[s].setFromProjectionMatrix(Ig,r.coordinateSystem,r.reversedDepth)}return this._count=t.length,this}getFrustum(e){return this._frustums[e]}intersectsObject(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsObject(e))return!0;return!1}intersectsSprite(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsSprite(e))return!0;return!1}intersectsSphere(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsSphere(e))return!0;return!1}intersectsBox(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].intersectsBox(e))return!0;return!1}containsPoint(e){let t=this._frustums;for(let i=0;i<this._count;i++)if(t[i].containsPoint(e))return!0;return!1}copy(e){this.coordinateSystem=e.coordinateSystem;let t=this._frustums,i=e._frustums;for(let s=0;s<e._count;s++)t[s]===void 0&&(t[s]=new Ar),t[s].copy(i[s]);return this._count=e._count,this}clone(){return new n().copy(this)}};var Ao=class extends bs{constructor(e){super(),this.isLineBasicMaterial=!0,this.type="LineBasicMaterial",this.color=new gt(16777215),this.map=null,this.linewidth=1,this.linecap="round",this.linejoin="round",this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.linewidth=e.linewidth,this.linecap=e.linecap,this.linejoin=e.linejoin,this.fog=e.fog,this}},Ic=new K,Pc=new K,Pg=new en,_a=new Qs,rc=new js,Sf=new K,Lg=new K,Lc=class extends Jn{constructor(e=new jn,t=new Ao){super(),this.isLine=!0,this.type="Line",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}computeLineDistances(){let e=this.geometry;if(e.index===null){let t=e.attributes.position,i=[0];for(let s=1,r=t.count;s<r;s++)Ic.fromBufferAttribute(t,s-1),Pc.fromBufferAttribute(t,s),i[s]=i[s-1],i[s]+=Ic.distanceTo(Pc);e.setAttribute("lineDistance",new Pn(i,1))}else Je("Line.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,s=this.matrixWorld,r=e.params.Line.threshold,o=i.drawRange;if(i.boundingSphere===null&&i.computeBoundingSphere(),rc.copy(i.boundingSphere),rc.applyMatrix4(s),rc.radius+=r,e.ray.intersectsSphere(rc)===!1)return;Pg.copy(s).invert(),_a.copy(e.ray).applyMatrix4(Pg);let a=r/((this.scale.x+this.scale.y+this.scale.z)/3),l=a*a,c=this.isLineSegments?2:1,h=i.index,u=i.attributes.position;if(h!==null){let p=Math.max(0,o.start),g=Math.min(h.count,o.start+o.count);for(let S=p,d=g-1;S<d;S+=c){let m=h.getX(S),y=h.getX(S+1),A=oc(this,e,_a,l,m,y,S);A&&t.push(A)}if(this.isLineLoop){let S=h.getX(g-1),d=h.getX(p),m=oc(this,e,_a,l,S,d,g-1);m&&t.push(m)}}else{let p=Math.max(0,o.start),g=Math.min(u.count,o.start+o.count);for(let S=p,d=g-1;S<d;S+=c){let m=oc(this,e,_a,l,S,S+1,S);m&&t.push(m)}if(this.isLineLoop){let S=oc(this,e,_a,l,g-1,p,g-1);S&&t.push(S)}}}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}};function oc(n,e,t,i,s,r,o){let a=n.geometry.attributes.position;if(Ic.fromBufferAttribute(a,s),Pc.fromBufferAttribute(a,r),t.distanceSqToSegment(Ic,Pc,Sf,Lg)>i)return;Sf.applyMatrix4(n.matrixWorld);let c=e.ray.origin.distanceTo(Sf);if(!(c<e.near||c>e.far))return{distance:c,point:Lg.clone().applyMatrix4(n.matrixWorld),index:o,face:null,faceIndex:null,barycoord:null,object:n}}var Ng=new K,Dg=new K,Pa=class extends Lc{constructor(e,t){super(e,t),this.isLineSegments=!0,this.type="LineSegments"}computeLineDistances(){let e=this.geometry;if(e.index===null){let t=e.attributes.position,i=[];for(let s=0,r=t.count;s<r;s+=2)Ng.fromBufferAttribute(t,s),Dg.fromBufferAttribute(t,s+1),i[s]=s===0?0:i[s-1],i[s+1]=i[s]+Ng.distanceTo(Dg);e.setAttribute("lineDistance",new Pn(i,1))}else Je("LineSegments.computeLineDistances(): Computation only possible with non-indexed BufferGeometry.");return this}};var Ro=class extends bs{constructor(e){super(),this.isPointsMaterial=!0,this.type="PointsMaterial",this.color=new gt(16777215),this.map=null,this.alphaMap=null,this.size=1,this.sizeAttenuation=!0,this.fog=!0,this.setValues(e)}copy(e){return super.copy(e),this.color.copy(e.color),this.map=e.map,this.alphaMap=e.alphaMap,this.size=e.size,this.sizeAttenuation=e.sizeAttenuation,this.fog=e.fog,this}},Ug=new en,Tf=new Qs,ac=new js,lc=new K,La=class extends Jn{constructor(e=new jn,t=new Ro){super(),this.isPoints=!0,this.type="Points",this.geometry=e,this.material=t,this.morphTargetDictionary=void 0,this.morphTargetInfluences=void 0,this.updateMorphTargets()}copy(e,t){return super.copy(e,t),e.morphTargetInfluences!==void 0?this.morphTargetInfluences=e.morphTargetInfluences.slice():this.morphTargetInfluences=void 0,e.morphTargetDictionary!==void 0?this.morphTargetDictionary=Object.assign({},e.morphTargetDictionary):this.morphTargetDictionary=void 0,this.material=Array.isArray(e.material)?e.material.slice():e.material,this.geometry=e.geometry,this}intersectsFrustum(e){return e.intersectsObject(this)}raycast(e,t){let i=this.geometry,s=this.matrixWorld,r=e.params.Points.threshold,o=i.drawRange;if(i.boundingSphere===null&&i.computeBoundingSphere(),ac.copy(i.boundingSphere),ac.applyMatrix4(s),ac.radius+=r,e.ray.intersectsSphere(ac)===!1)return;Ug.copy(s).invert(),Tf.copy(e.ray).applyMatrix4(Ug);let a=r/((this.scale.x+this.scale.y+this.scale.z)/3),l=a*a,c=i.index,f=i.attributes.position;if(c!==null){let u=Math.max(0,o.start),p=Math.min(c.count,o.start+o.count);for(let g=u,S=p;g<S;g++){let d=c.getX(g);lc.fromBufferAttribute(f,d),Og(lc,d,l,s,e,t,this)}}else{let u=Math.max(0,o.start),p=Math.min(f.count,o.start+o.count);for(let g=u,S=p;g<S;g++)lc.fromBufferAttribute(f,g),Og(lc,g,l,s,e,t,this)}}updateMorphTargets(){let t=this.geometry.morphAttributes,i=Object.keys(t);if(i.length>0){let s=t[i[0]];if(s!==void 0){this.morphTargetInfluences=[],this.morphTargetDictionary={};for(let r=0,o=s.length;r<o;r++){let a=s[r].name||String(r);this.morphTargetInfluences.push(0),this.morphTargetDictionary[a]=r}}}}};function Og(n,e,t,i,s,r,o){let a=Tf.distanceSqToPoint(n);if(a<t){let l=new K;Tf.closestPointToPoint(n,l),l.applyMatrix4(i);let c=s.ray.origin.distanceTo(l);if(c<s.near||c>s.far)return;r.push({distance:c,distanceToRay:Math.sqrt(a),point:l,index:e,face:null,faceIndex:null,barycoord:null,object:o})}}var Na=class extends Kn{constructor(e=[],t=Ir,i,s,r,o,a,l,c,h){super(e,t,i,s,r,o,a,l,c,h),this.isCubeTexture=!0,this.flipY=!1}get images(){return this.image}set images(e){this.image=e}};var Ms=class extends Kn{constructor(e,t,i=Ui,s,r,o,a=Ln,l=Ln,c,h=Ss,f=1){if(h!==Ss&&h!==Es)throw new Error("THREE.DepthTexture: format must be either THREE.DepthFormat or THREE.DepthStencilFormat");let u={width:e,height:t,depth:f};super(u,s,r,o,a,l,h,i,c),this.isDepthTexture=!0,this.flipY=!1,this.generateMipmaps=!1,this.compareFunction=null}copy(e){return super.copy(e),this.source=new Eo(Object.assign({},e.image)),this.compareFunction=e.compareFunction,this}toJSON(e){let t=super.toJSON(e);return t.compareFunction=this.compareFunction,t}},Da=class extends Ms{constructor(e,t=Ui,i=Ir,s,r,o=Ln,a=Ln,l,c=Ss){let h={width:e,height:e,depth:1},f=[h,h,h,h,h,h];super(e,e,t,i,s,r,o,a,l,c),this.image=f,this.isCubeDepthTexture=!0,this.isCubeTexture=!0}get images(){return this.image}set images(e){this.image=e}},Ua=class extends Kn{constructor(e=null){super(),this.sourceTexture=e,this.isExternalTexture=!0}copy(e){return super.copy(e),this.sourceTexture=e.sourceTexture,this}},Co=class n extends jn{constructor(e=1,t=1,i=1,s=1,r=1,o=1){super(),this.type="BoxGeometry",this.parameters={width:e,height:t,depth:i,widthSegments:s,heightSegments:r,depthSegments:o};let a=this;s=Math.floor(s),r=Math.floor(r),o=Math.floor(o);let l=[],c=[],h=[],f=[],u=0,p=0;g("z","y","x",-1,-1,i,t,e,o,r,0),g("z","y","x",1,-1,i,t,-e,o,r,1),g("x","z","y",1,1,e,i,t,s,o,2),g("x","z","y",1,-1,e,i,-t,s,o,3),g("x","y","z",1,-1,e,t,i,s,r,4),g("x","y","z",-1,-1,e,t,-i,s,r,5),this.setIndex(l),this.setAttribute("position",new Pn(c,3)),this.setAttribute("normal",new Pn(h,3)),this.setAttribute("uv",new Pn(f,2));function g(S,d,m,y,A,b,C,E,x,T,k){let U=b/x,P=C/T,B=b/2,z=C/2,L=E/2,H=x+1,W=T+1,D=0,te=0,X=new K;for(let q=0;q<W;q++){let j=q*P-z;for(let ae=0;ae<H;ae++){let ce=ae*U-B;X[S]=ce*y,X[d]=j*A,X[m]=L,c.push(X.x,X.y,X.z),X[S]=0,X[d]=0,X[m]=E>0?1:-1,h.push(X.x,X.y,X.z),f.push(ae/x),f.push(1-q/T),D+=1}}for(let q=0;q<T;q++)for(let j=0;j<x;j++){let ae=u+j+H*q,ce=u+j+H*(q+1),ee=u+(j+1)+H*(q+1),pe=u+(j+1)+H*q;l.push(ae,ce,pe),l.push(ce,ee,pe),te+=6}a.addGroup(p,te,k),p+=te,u+=D}}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new n(e.width,e.height,e.depth,e.widthSegments,e.heightSegments,e.depthSegments)}};var Oa=class n extends jn{constructor(e=1,t=1,i=1,s=1){super(),this.type="PlaneGeometry",this.parameters={width:e,height:t,widthSegments:i,heightSegments:s};let r=e/2,o=t/2,a=Math.floor(i),l=Math.floor(s),c=a+1,h=l+1,f=e/a,u=t/l,p=[],g=[],S=[],d=[];for(let m=0;m<h;m++){let y=m*u-o;for(let A=0;A<c;A++){let b=A*f-r;g.push(b,-y,0),S.push(0,0,1),d.push(A/a),d.push(1-m/l)}}for(let m=0;m<l;m++)for(let y=0;y<a;y++){let A=y+c*m,b=y+c*(m+1),C=y+1+c*(m+1),E=y+1+c*m;p.push(A,b,E),p.push(b,C,E)}this.setIndex(p),this.setAttribute("position",new Pn(g,3)),this.setAttribute("normal",new Pn(S,3)),this.setAttribute("uv",new Pn(d,2))}copy(e){return super.copy(e),this.parameters=Object.assign({},e.parameters),this}static fromJSON(e){return new n(e.width,e.height,e.widthSegments,e.heightSegments)}};function Lr(n){let e={};for(let t in n){e[t]={};for(let i in n[t]){let s=n[t][i];if(Fg(s))s.isRenderTargetTexture?(Je("UniformsUtils: Textures of render targets cannot be cloned via cloneUniforms() or mergeUniforms()."),e[t][i]=null):e[t][i]=s.clone();else if(Array.isArray(s))if(Fg(s[0])){let r=[];for(let o=0,a=s.length;o<a;o++)r[o]=s[o].clone();e[t][i]=r}else e[t][i]=s.slice();else e[t][i]=s}}return e}function kn(n){let e={};for(let t=0;t<n.length;t++){let i=Lr(n[t]);for(let s in i)e[s]=i[s]}return e}function Fg(n){return n&&(n.isColor||n.isMatrix3||n.isMatrix4||n.isVector2||n.isVector3||n.isVector4||n.isTexture||n.isQuaternion)}function Bv(n){let e=[];for(let t=0;t<n.length;t++)e.push(n[t].clone());return e}function ad(n){let e=n.getRenderTarget();return e===null?n.outputColorSpace:e.isXRRenderTarget===!0?e.texture.colorSpace:At.workingColorSpace}var R0={clone:Lr,merge:kn},kv=`void main() {
	gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
}`,zv=`void main() {
	gl_FragColor = vec4( 1.0, 0.0, 0.0, 1.0 );
}`,Qi=class extends bs{constructor(e){super(),this.isShaderMaterial=!0,this.type="ShaderMaterial",this.defines={},this.uniforms={},this.uniformsGroups=[],this.vertexShader=kv,this.fragmentShader=zv,this.linewidth=1,this.wireframe=!1,this.wireframeLinewidth=1,this.fog=!1,this.lights=!1,this.clipping=!1,this.forceSinglePass=!0,this.extensions={clipCullDistance:!1,multiDraw:!1},this.defaultAttributeValues={color:[1,1,1],uv:[0,0],uv1:[0,0]},this.index0AttributeName=void 0,this.uniformsNeedUpdate=!1,this.glslVersion=null,e!==void 0&&this.setValues(e)}copy(e){return super.copy(e),this.fragmentShader=e.fragmentShader,this.vertexShader=e.vertexShader,this.uniforms=Lr(e.uniforms),this.uniformsGroups=Bv(e.uniformsGroups),this.defines=Object.assign({},e.defines),this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this.fog=e.fog,this.lights=e.lights,this.clipping=e.clipping,this.extensions=Object.assign({},e.extensions),this.glslVersion=e.glslVersion,this.defaultAttributeValues=Object.assign({},e.defaultAttributeValues),this.index0AttributeName=e.index0AttributeName,this.uniformsNeedUpdate=e.uniformsNeedUpdate,this}toJSON(e){let t=super.toJSON(e);t.glslVersion=this.glslVersion,t.uniforms={};for(let s in this.uniforms){let o=this.uniforms[s].value;o&&o.isTexture?t.uniforms[s]={type:"t",value:o.toJSON(e).uuid}:o&&o.isColor?t.uniforms[s]={type:"c",value:o.getHex()}:o&&o.isVector2?t.uniforms[s]={type:"v2",value:o.toArray()}:o&&o.isVector3?t.uniforms[s]={type:"v3",value:o.toArray()}:o&&o.isVector4?t.uniforms[s]={type:"v4",value:o.toArray()}:o&&o.isMatrix3?t.uniforms[s]={type:"m3",value:o.toArray()}:o&&o.isMatrix4?t.uniforms[s]={type:"m4",value:o.toArray()}:t.uniforms[s]={value:o}}Object.keys(this.defines).length>0&&(t.defines=this.defines),t.vertexShader=this.vertexShader,t.fragmentShader=this.fragmentShader,t.lights=this.lights,t.clipping=this.clipping;let i={};for(let s in this.extensions)this.extensions[s]===!0&&(i[s]=!0);return Object.keys(i).length>0&&(t.extensions=i),t}fromJSON(e,t){if(super.fromJSON(e,t),e.uniforms!==void 0)for(let i in e.uniforms){let s=e.uniforms[i];switch(this.uniforms[i]={},s.type){case"t":this.uniforms[i].value=t[s.value]||null;break;case"c":this.uniforms[i].value=new gt().setHex(s.value);break;case"v2":this.uniforms[i].value=new ut().fromArray(s.value);break;case"v3":this.uniforms[i].value=new K().fromArray(s.value);break;case"v4":this.uniforms[i].value=new sn().fromArray(s.value);break;case"m3":this.uniforms[i].value=new ot().fromArray(s.value);break;case"m4":this.uniforms[i].value=new en().fromArray(s.value);break;default:this.uniforms[i].value=s.value}}if(e.defines!==void 0&&(this.defines=e.defines),e.vertexShader!==void 0&&(this.vertexShader=e.vertexShader),e.fragmentShader!==void 0&&(this.fragmentShader=e.fragmentShader),e.glslVersion!==void 0&&(this.glslVersion=e.glslVersion),e.extensions!==void 0)for(let i in e.extensions)this.extensions[i]=e.extensions[i];return e.lights!==void 0&&(this.lights=e.lights),e.clipping!==void 0&&(this.clipping=e.clipping),this}},Nc=class extends Qi{constructor(e){super(e),this.isRawShaderMaterial=!0,this.type="RawShaderMaterial"}};var Dc=class extends bs{constructor(e){super(),this.isMeshDepthMaterial=!0,this.type="MeshDepthMaterial",this.depthPacking=f0,this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.wireframe=!1,this.wireframeLinewidth=1,this.setValues(e)}copy(e){return super.copy(e),this.depthPacking=e.depthPacking,this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this.wireframe=e.wireframe,this.wireframeLinewidth=e.wireframeLinewidth,this}},Uc=class extends bs{constructor(e){super(),this.isMeshDistanceMaterial=!0,this.type="MeshDistanceMaterial",this.map=null,this.alphaMap=null,this.displacementMap=null,this.displacementScale=1,this.displacementBias=0,this.setValues(e)}copy(e){return super.copy(e),this.map=e.map,this.alphaMap=e.alphaMap,this.displacementMap=e.displacementMap,this.displacementScale=e.displacementScale,this.displacementBias=e.displacementBias,this}};function xo(n,e){return!n||n.constructor===e?n:typeof e.BYTES_PER_ELEMENT=="number"?new e(n):Array.prototype.slice.call(n)}function cc(n){return n!==void 0&&n.inTangents!==void 0&&n.outTangents!==void 0}var er=class{constructor(e,t,i,s){this.parameterPositions=e,this._cachedIndex=0,this.resultBuffer=s!==void 0?s:new t.constructor(i),this.sampleValues=t,this.valueSize=i,this.settings=null,this.DefaultSettings_={}}evaluate(e){let t=this.parameterPositions,i=this._cachedIndex,s=t[i],r=t[i-1];n:{e:{let o;t:{i:if(!(e<s)){for(let a=i+2;;){if(s===void 0){if(e<r)break i;return i=t.length,this._cachedIndex=i,this.copySampleValue_(i-1)}if(i===a)break;if(r=s,s=t[++i],e<s)break e}o=t.length;break t}if(!(e>=r)){let a=t[1];e<a&&(i=2,r=a);for(let l=i-2;;){if(r===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(i===l)break;if(s=r,r=t[--i-1],e>=r)break e}o=i,i=0;break t}break n}for(;i<o;){let a=i+o>>>1;e<t[a]?o=a:i=a+1}if(s=t[i],r=t[i-1],r===void 0)return this._cachedIndex=0,this.copySampleValue_(0);if(s===void 0)return i=t.length,this._cachedIndex=i,this.copySampleValue_(i-1)}this._cachedIndex=i,this.intervalChanged_(i,r,s)}return this.interpolate_(i,r,e,s)}getSettings_(){return this.settings||this.DefaultSettings_}copySampleValue_(e){let t=this.resultBuffer,i=this.sampleValues,s=this.valueSize,r=e*s;for(let o=0;o!==s;++o)t[o]=i[r+o];return t}interpolate_(){throw new Error("THREE.Interpolant: Call to abstract method.")}intervalChanged_(){}},Oc=class extends er{constructor(e,t,i,s){super(e,t,i,s),this._weightPrev=-0,this._offsetPrev=-0,this._weightNext=-0,this._offsetNext=-0,this.DefaultSettings_={endingStart:Mf,endingEnd:Mf}}intervalChanged_(e,t,i){let s=this.parameterPositions,r=e-2,o=e+1,a=s[r],l=s[o];if(a===void 0)switch(this.getSettings_().endingStart){case wf:r=e,a=2*t-i;break;case Ef:r=s.length-2,a=t+s[r]-s[r+1];break;default:r=e,a=i}if(l===void 0)switch(this.getSettings_().endingEnd){case wf:o=e,l=2*i-t;break;case Ef:o=1,l=i+s[1]-s[0];break;default:o=e-1,l=t}let c=(i-t)*.5,h=this.valueSize;this._weightPrev=c/(t-a),this._weightNext=c/(l-i),this._offsetPrev=r*h,this._offsetNext=o*h}interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=e*a,c=l-a,h=this._offsetPrev,f=this._offsetNext,u=this._weightPrev,p=this._weightNext,g=(i-t)/(s-t),S=g*g,d=S*g,m=-u*d+2*u*S-u*g,y=(1+u)*d+(-1.5-2*u)*S+(-.5+u)*g+1,A=(-1-p)*d+(1.5+p)*S+.5*g,b=p*d-p*S;for(let C=0;C!==a;++C)r[C]=m*o[h+C]+y*o[c+C]+A*o[l+C]+b*o[f+C];return r}},Fc=class extends er{constructor(e,t,i,s){super(e,t,i,s)}interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=e*a,c=l-a,h=(i-t)/(s-t),f=1-h;for(let u=0;u!==a;++u)r[u]=o[c+u]*f+o[l+u]*h;return r}},Bc=class extends er{constructor(e,t,i,s){super(e,t,i,s)}interpolate_(e){return this.copySampleValue_(e-1)}},kc=class extends er{interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=e*a,c=l-a,h=this.inTangents,f=this.outTangents;if(!h||!f){let g=(i-t)/(s-t),S=1-g;for(let d=0;d!==a;++d)r[d]=o[c+d]*S+o[l+d]*g;return r}let u=a*2,p=e-1;for(let g=0;g!==a;++g){let S=o[c+g],d=o[l+g],m=p*u+g*2,y=f[m],A=f[m+1],b=e*u+g*2,C=h[b],E=h[b+1],x=Hv(i,t,y,C,s);r[g]=C0(x,S,A,E,d)}return r}};function C0(n,e,t,i,s){let r=1-n;return r*r*r*e+3*r*r*n*t+3*r*n*n*i+n*n*n*s}function Gv(n,e,t,i,s){let r=1-n;return 3*r*r*(t-e)+6*r*n*(i-t)+3*n*n*(s-i)}function Hv(n,e,t,i,s){let r=(n-e)/(s-e);for(let o=0;o<8;o++){let a=C0(r,e,t,i,s)-n;if(Math.abs(a)<1e-10)break;let l=Gv(r,e,t,i,s);if(Math.abs(l)<1e-10)break;r=Math.max(0,Math.min(1,r-a/l))}return r}var mi=class{constructor(e,t,i,s){if(e===void 0)throw new Error("THREE.KeyframeTrack: track name is undefined");if(t===void 0||t.length===0)throw new Error("THREE.KeyframeTrack: no keyframes in track named "+e);this.name=e,this.times=xo(t,this.TimeBufferType),this.values=xo(i,this.ValueBufferType),this.setInterpolation(s||this.DefaultInterpolation)}static toJSON(e){let t=e.constructor,i;if(t.toJSON!==this.toJSON)i=t.toJSON(e);else{i={name:e.name,times:xo(e.times,Array),values:xo(e.values,Array)};let s=e.getInterpolation();s!==e.DefaultInterpolation&&(i.interpolation=s),cc(e.settings)&&(i.settings={inTangents:xo(e.settings.inTangents,Array),outTangents:xo(e.settings.outTangents,Array)})}return i.type=e.ValueTypeName,i}InterpolantFactoryMethodDiscrete(e){return new Bc(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodLinear(e){return new Fc(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodSmooth(e){return new Oc(this.times,this.values,this.getValueSize(),e)}InterpolantFactoryMethodBezier(e){let t=new kc(this.times,this.values,this.getValueSize(),e);return this.settings&&(t.inTangents=this.settings.inTangents,t.outTangents=this.settings.outTangents),t}setInterpolation(e){let t;switch(e){case Sa:t=this.InterpolantFactoryMethodDiscrete;break;case Mc:t=this.InterpolantFactoryMethodLinear;break;case fc:t=this.InterpolantFactoryMethodSmooth;break;case bf:t=this.InterpolantFactoryMethodBezier;break}if(t===void 0){let i="unsupported interpolation for "+this.ValueTypeName+" keyframe track named "+this.name;if(this.createInterpolant===void 0)if(e!==this.DefaultInterpolation)this.setInterpolation(this.DefaultInterpolation);else throw new Error(i);return Je("KeyframeTrack:",i),this}return this.createInterpolant=t,this}getInterpolation(){switch(this.createInterpolant){case this.InterpolantFactoryMethodDiscrete:return Sa;case this.InterpolantFactoryMethodLinear:return Mc;case this.InterpolantFactoryMethodSmooth:return fc;case this.InterpolantFactoryMethodBezier:return bf}}getValueSize(){return this.values.length/this.times.length}shift(e){if(e!==0){let t=this.times;for(let i=0,s=t.length;i!==s;++i)t[i]+=e;cc(this.settings)&&(Bg(this.settings.inTangents,e),Bg(this.settings.outTangents,e))}return this}scale(e){if(e!==1){let t=this.times;for(let i=0,s=t.length;i!==s;++i)t[i]*=e;cc(this.settings)&&(kg(this.settings.inTangents,e),kg(this.settings.outTangents,e))}return this}trim(e,t){let i=this.times,s=i.length,r=0,o=s-1;for(;r!==s&&i[r]<e;)++r;for(;o!==-1&&i[o]>t;)--o;if(++o,r!==0||o!==s){r>=o&&(o=Math.max(o,1),r=o-1);let a=this.getValueSize();this.times=i.slice(r,o),this.values=this.values.slice(r*a,o*a)}return this}validate(){let e=!0,t=this.getValueSize();t-Math.floor(t)!==0&&(rt("KeyframeTrack: Invalid value size in track.",this),e=!1);let i=this.times,s=this.values,r=i.length;r===0&&(rt("KeyframeTrack: Track is empty.",this),e=!1);let o=null;for(let a=0;a!==r;a++){let l=i[a];if(typeof l=="number"&&isNaN(l)){rt("KeyframeTrack: Time is not a valid number.",this,a,l),e=!1;break}if(o!==null&&o>l){rt("KeyframeTrack: Out of order keys.",this,a,l,o),e=!1;break}o=l}if(s!==void 0&&sv(s))for(let a=0,l=s.length;a!==l;++a){let c=s[a];if(isNaN(c)){rt("KeyframeTrack: Value is not a valid number.",this,a,c),e=!1;break}}return e}optimize(){let e=this.times.slice(),t=this.values.slice(),i=this.getValueSize(),s=this.getInterpolation()===fc,r=e.length-1,o=1;for(let a=1;a<r;++a){let l=!1,c=e[a],h=e[a+1];if(c!==h&&(a!==1||c!==e[0]))if(s)l=!0;else{let f=a*i,u=f-i,p=f+i;for(let g=0;g!==i;++g){let S=t[f+g];if(S!==t[u+g]||S!==t[p+g]){l=!0;break}}}if(l){if(a!==o){e[o]=e[a];let f=a*i,u=o*i;for(let p=0;p!==i;++p)t[u+p]=t[f+p]}++o}}if(r>0){e[o]=e[r];for(let a=r*i,l=o*i,c=0;c!==i;++c)t[l+c]=t[a+c];++o}return o!==e.length?(this.times=e.slice(0,o),this.values=t.slice(0,o*i)):(this.times=e,this.values=t),this}clone(){let e=this.times.slice(),t=this.values.slice(),i=this.constructor,s=new i(this.name,e,t);return s.createInterpolant=this.createInterpolant,cc(this.settings)&&(s.settings={inTangents:this.settings.inTangents.slice(),outTangents:this.settings.outTangents.slice()}),s}};function Bg(n,e){for(let t=0,i=n.length;t!==i;t+=2)n[t]+=e}function kg(n,e){for(let t=0,i=n.length;t!==i;t+=2)n[t]*=e}mi.prototype.ValueTypeName="";mi.prototype.TimeBufferType=Float32Array;mi.prototype.ValueBufferType=Float32Array;mi.prototype.DefaultInterpolation=Mc;var tr=class extends mi{constructor(e,t,i){super(e,t,i)}};tr.prototype.ValueTypeName="bool";tr.prototype.ValueBufferType=Array;tr.prototype.DefaultInterpolation=Sa;tr.prototype.InterpolantFactoryMethodLinear=void 0;tr.prototype.InterpolantFactoryMethodSmooth=void 0;var zc=class extends mi{constructor(e,t,i,s){super(e,t,i,s)}};zc.prototype.ValueTypeName="color";var Gc=class extends mi{constructor(e,t,i,s){super(e,t,i,s)}};Gc.prototype.ValueTypeName="number";var Hc=class extends er{constructor(e,t,i,s){super(e,t,i,s)}interpolate_(e,t,i,s){let r=this.resultBuffer,o=this.sampleValues,a=this.valueSize,l=(i-t)/(s-t),c=e*a;for(let h=c+a;c!==h;c+=4)di.slerpFlat(r,0,o,c-a,o,c,l);return r}},Fa=class extends mi{constructor(e,t,i,s){super(e,t,i,s)}InterpolantFactoryMethodLinear(e){return new Hc(this.times,this.values,this.getValueSize(),e)}};Fa.prototype.ValueTypeName="quaternion";Fa.prototype.InterpolantFactoryMethodSmooth=void 0;var nr=class extends mi{constructor(e,t,i){super(e,t,i)}};nr.prototype.ValueTypeName="string";nr.prototype.ValueBufferType=Array;nr.prototype.DefaultInterpolation=Sa;nr.prototype.InterpolantFactoryMethodLinear=void 0;nr.prototype.InterpolantFactoryMethodSmooth=void 0;var Vc=class extends mi{constructor(e,t,i,s){super(e,t,i,s)}};Vc.prototype.ValueTypeName="vector";var Wc=class{constructor(e,t,i){let s=this,r=!1,o=0,a=0,l,c=[];this.onStart=void 0,this.onLoad=e,this.onProgress=t,this.onError=i,this._abortController=null,this.itemStart=function(h){a++,r===!1&&s.onStart!==void 0&&s.onStart(h,o,a),r=!0},this.itemEnd=function(h){o++,s.onProgress!==void 0&&s.onProgress(h,o,a),o===a&&(r=!1,s.onLoad!==void 0&&s.onLoad())},this.itemError=function(h){s.onError!==void 0&&s.onError(h)},this.resolveURL=function(h){return h=h.normalize("NFC"),l?l(h):h},this.setURLModifier=function(h){return l=h,this},this.addHandler=function(h,f){return c.push(h,f),this},this.removeHandler=function(h){let f=c.indexOf(h);return f!==-1&&c.splice(f,2),this},this.getHandler=function(h){for(let f=0,u=c.length;f<u;f+=2){let p=c[f],g=c[f+1];if(p.global&&(p.lastIndex=0),p.test(h))return g}return null},this.abort=function(){return this.abortController.abort(),this._abortController=null,this}}get abortController(){return this._abortController||(this._abortController=new AbortController),this._abortController}},I0=new Wc,Xc=class{constructor(e){this.manager=e!==void 0?e:I0,this.crossOrigin="anonymous",this.withCredentials=!1,this.path="",this.resourcePath="",this.requestHeader={},this.priority="auto",this.cache="default",typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}load(){}loadAsync(e,t){let i=this;return new Promise(function(s,r){i.load(e,s,t,r)})}parse(){}setCrossOrigin(e){return this.crossOrigin=e,this}setWithCredentials(e){return this.withCredentials=e,this}setPath(e){return this.path=e,this}setResourcePath(e){return this.resourcePath=e,this}setRequestHeader(e){return this.requestHeader=e,this}setPriority(e){return this.priority=e,this}setCache(e){return this.cache=e,this}abort(){return this}};Xc.DEFAULT_MATERIAL_NAME="__DEFAULT";var hc=new K,uc=new di,Ki=new K,Ba=class extends Jn{constructor(){super(),this.isCamera=!0,this.type="Camera",this.matrixWorldInverse=new en,this.projectionMatrix=new en,this.projectionMatrixInverse=new en,this.coordinateSystem=Mi,this._reversedDepth=!1}get reversedDepth(){return this._reversedDepth}copy(e,t){return super.copy(e,t),this.matrixWorldInverse.copy(e.matrixWorldInverse),this.projectionMatrix.copy(e.projectionMatrix),this.projectionMatrixInverse.copy(e.projectionMatrixInverse),this.coordinateSystem=e.coordinateSystem,this}getWorldDirection(e){return super.getWorldDirection(e).negate()}updateMatrixWorld(e){super.updateMatrixWorld(e),this.matrixWorld.decompose(hc,uc,Ki),Ki.x===1&&Ki.y===1&&Ki.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(hc,uc,Ki.set(1,1,1)).invert()}updateWorldMatrix(e,t,i=!1){super.updateWorldMatrix(e,t,i),this.matrixWorld.decompose(hc,uc,Ki),Ki.x===1&&Ki.y===1&&Ki.z===1?this.matrixWorldInverse.copy(this.matrixWorld).invert():this.matrixWorldInverse.compose(hc,uc,Ki.set(1,1,1)).invert()}clone(){return new this.constructor().copy(this)}},$s=new K,zg=new ut,Gg=new ut,qn=class extends Ba{constructor(e=50,t=1,i=.1,s=2e3){super(),this.isPerspectiveCamera=!0,this.type="PerspectiveCamera",this.fov=e,this.zoom=1,this.near=i,this.far=s,this.focus=10,this.aspect=t,this.view=null,this.filmGauge=35,this.filmOffset=0,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.fov=e.fov,this.zoom=e.zoom,this.near=e.near,this.far=e.far,this.focus=e.focus,this.aspect=e.aspect,this.view=e.view===null?null:Object.assign({},e.view),this.filmGauge=e.filmGauge,this.filmOffset=e.filmOffset,this}setFocalLength(e){let t=.5*this.getFilmHeight()/e;this.fov=wo*2*Math.atan(t),this.updateProjectionMatrix()}getFocalLength(){let e=Math.tan(ya*.5*this.fov);return .5*this.getFilmHeight()/e}getEffectiveFOV(){return wo*2*Math.atan(Math.tan(ya*.5*this.fov)/this.zoom)}getFilmWidth(){return this.filmGauge*Math.min(this.aspect,1)}getFilmHeight(){return this.filmGauge/Math.max(this.aspect,1)}getViewBounds(e,t,i){$s.set(-1,-1,.5).applyMatrix4(this.projectionMatrixInverse),t.set($s.x,$s.y).multiplyScalar(-e/$s.z),$s.set(1,1,.5).applyMatrix4(this.projectionMatrixInverse),i.set($s.x,$s.y).multiplyScalar(-e/$s.z)}getViewSize(e,t){return this.getViewBounds(e,zg,Gg),t.subVectors(Gg,zg)}setViewOffset(e,t,i,s,r,o){this.aspect=e/t,this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=i,this.view.offsetY=s,this.view.width=r,this.view.height=o,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=this.near,t=e*Math.tan(ya*.5*this.fov)/this.zoom,i=2*t,s=this.aspect*i,r=-.5*s,o=this.view;if(this.view!==null&&this.view.enabled){let l=o.fullWidth,c=o.fullHeight;r+=o.offsetX*s/l,t-=o.offsetY*i/c,s*=o.width/l,i*=o.height/c}let a=this.filmOffset;a!==0&&(r+=e*a/this.getFilmWidth()),this.projectionMatrix.makePerspective(r,r+s,t,t-i,e,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.fov=this.fov,t.object.zoom=this.zoom,t.object.near=this.near,t.object.far=this.far,t.object.focus=this.focus,t.object.aspect=this.aspect,this.view!==null&&(t.object.view=Object.assign({},this.view)),t.object.filmGauge=this.filmGauge,t.object.filmOffset=this.filmOffset,t}};var qc=class extends Ba{constructor(e=-1,t=1,i=1,s=-1,r=.1,o=2e3){super(),this.isOrthographicCamera=!0,this.type="OrthographicCamera",this.zoom=1,this.view=null,this.left=e,this.right=t,this.top=i,this.bottom=s,this.near=r,this.far=o,this.updateProjectionMatrix()}copy(e,t){return super.copy(e,t),this.left=e.left,this.right=e.right,this.top=e.top,this.bottom=e.bottom,this.near=e.near,this.far=e.far,this.zoom=e.zoom,this.view=e.view===null?null:Object.assign({},e.view),this}setViewOffset(e,t,i,s,r,o){this.view===null&&(this.view={enabled:!0,fullWidth:1,fullHeight:1,offsetX:0,offsetY:0,width:1,height:1}),this.view.enabled=!0,this.view.fullWidth=e,this.view.fullHeight=t,this.view.offsetX=i,this.view.offsetY=s,this.view.width=r,this.view.height=o,this.updateProjectionMatrix()}clearViewOffset(){this.view!==null&&(this.view.enabled=!1),this.updateProjectionMatrix()}updateProjectionMatrix(){let e=(this.right-this.left)/(2*this.zoom),t=(this.top-this.bottom)/(2*this.zoom),i=(this.right+this.left)/2,s=(this.top+this.bottom)/2,r=i-e,o=i+e,a=s+t,l=s-t;if(this.view!==null&&this.view.enabled){let c=(this.right-this.left)/this.view.fullWidth/this.zoom,h=(this.top-this.bottom)/this.view.fullHeight/this.zoom;r+=c*this.view.offsetX,o=r+c*this.view.width,a-=h*this.view.offsetY,l=a-h*this.view.height}this.projectionMatrix.makeOrthographic(r,o,a,l,this.near,this.far,this.coordinateSystem,this.reversedDepth),this.projectionMatrixInverse.copy(this.projectionMatrix).invert()}toJSON(e){let t=super.toJSON(e);return t.object.zoom=this.zoom,t.object.left=this.left,t.object.right=this.right,t.object.top=this.top,t.object.bottom=this.bottom,t.object.near=this.near,t.object.far=this.far,this.view!==null&&(t.object.view=Object.assign({},this.view)),t}};var yo=-90,vo=1,Io=class extends Jn{constructor(e,t,i){super(),this.type="CubeCamera",this.renderTarget=i,this.coordinateSystem=null,this.activeMipmapLevel=0;let s=new qn(yo,vo,e,t);s.layers=this.layers,this.add(s);let r=new qn(yo,vo,e,t);r.layers=this.layers,this.add(r);let o=new qn(yo,vo,e,t);o.layers=this.layers,this.add(o);let a=new qn(yo,vo,e,t);a.layers=this.layers,this.add(a);let l=new qn(yo,vo,e,t);l.layers=this.layers,this.add(l);let c=new qn(yo,vo,e,t);c.layers=this.layers,this.add(c)}updateCoordinateSystem(){let e=this.coordinateSystem,t=this.children.concat(),[i,s,r,o,a,l]=t;for(let c of t)this.remove(c);if(e===Mi)i.up.set(0,1,0),i.lookAt(1,0,0),s.up.set(0,1,0),s.lookAt(-1,0,0),r.up.set(0,0,-1),r.lookAt(0,1,0),o.up.set(0,0,1),o.lookAt(0,-1,0),a.up.set(0,1,0),a.lookAt(0,0,1),l.up.set(0,1,0),l.lookAt(0,0,-1);else if(e===wa)i.up.set(0,-1,0),i.lookAt(-1,0,0),s.up.set(0,-1,0),s.lookAt(1,0,0),r.up.set(0,0,1),r.lookAt(0,1,0),o.up.set(0,0,-1),o.lookAt(0,-1,0),a.up.set(0,-1,0),a.lookAt(0,0,1),l.up.set(0,-1,0),l.lookAt(0,0,-1);else throw new Error("THREE.CubeCamera.updateCoordinateSystem(): Invalid coordinate system: "+e);for(let c of t)this.add(c),c.updateMatrixWorld()}update(e,t){this.parent===null&&this.updateMatrixWorld();let{renderTarget:i,activeMipmapLevel:s}=this;this.coordinateSystem!==e.coordinateSystem&&(this.coordinateSystem=e.coordinateSystem,this.updateCoordinateSystem());let[r,o,a,l,c,h]=this.children,f=e.getRenderTarget(),u=e.getActiveCubeFace(),p=e.getActiveMipmapLevel(),g=e.xr.enabled;e.xr.enabled=!1;let S=i.texture.mipmapsAutoUpdate;i.texture.mipmapsAutoUpdate=!1;let d=!1;e.isWebGLRenderer===!0?d=e.state.buffers.depth.getReversed():d=e.reversedDepthBuffer,e.setRenderTarget(i,0,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,r),e.setRenderTarget(i,1,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,o),e.setRenderTarget(i,2,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,a),e.setRenderTarget(i,3,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,l),e.setRenderTarget(i,4,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,c),i.texture.mipmapsAutoUpdate=S,e.setRenderTarget(i,5,s),d&&e.autoClear===!1&&e.clearDepth(),e.render(t,h),e.setRenderTarget(f,u,p),e.xr.enabled=g,i.texture.needsPMREMUpdate=!0}},Yc=class extends qn{constructor(e=[]){super(),this.isArrayCamera=!0,this.isMultiViewCamera=!1,this.cameras=e,this.perCameraFrustumCulled=!1}};var ld="\\[\\]\\.:\\/",Vv=new RegExp("["+ld+"]","g"),cd="[^"+ld+"]",Wv="[^"+ld.replace("\\.","")+"]",Xv=/((?:WC+[\/:])*)/.source.replace("WC",cd),qv=/(WCOD+)?/.source.replace("WCOD",Wv),Yv=/(?:\.(WC+)(?:\[(.+)\])?)?/.source.replace("WC",cd),$v=/\.(WC+)(?:\[(.+)\])?/.source.replace("WC",cd),Zv=new RegExp("^"+Xv+qv+Yv+$v+"$"),Kv=["material","materials","bones","map"],Af=class{constructor(e,t,i){let s=i||jt.parseTrackName(t);this._targetGroup=e,this._bindings=e.subscribe_(t,s)}getValue(e,t){this.bind();let i=this._targetGroup.nCachedObjects_,s=this._bindings[i];s!==void 0&&s.getValue(e,t)}setValue(e,t){let i=this._bindings;for(let s=this._targetGroup.nCachedObjects_,r=i.length;s!==r;++s)i[s].setValue(e,t)}bind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,i=e.length;t!==i;++t)e[t].bind()}unbind(){let e=this._bindings;for(let t=this._targetGroup.nCachedObjects_,i=e.length;t!==i;++t)e[t].unbind()}},jt=class n{constructor(e,t,i){this.path=t,this.parsedPath=i||n.parseTrackName(t),this.node=n.findNode(e,this.parsedPath.nodeName),this.rootNode=e,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}static create(e,t,i){return e&&e.isAnimationObjectGroup?new n.Composite(e,t,i):new n(e,t,i)}static sanitizeNodeName(e){return e.replace(/\s/g,"_").replace(Vv,"")}static parseTrackName(e){let t=Zv.exec(e);if(t===null)throw new Error("THREE.PropertyBinding: Cannot parse trackName: "+e);let i={nodeName:t[2],objectName:t[3],objectIndex:t[4],propertyName:t[5],propertyIndex:t[6]},s=i.nodeName&&i.nodeName.lastIndexOf(".");if(s!==void 0&&s!==-1){let r=i.nodeName.substring(s+1);Kv.indexOf(r)!==-1&&(i.nodeName=i.nodeName.substring(0,s),i.objectName=r)}if(i.propertyName===null||i.propertyName.length===0)throw new Error("THREE.PropertyBinding: can not parse propertyName from trackName: "+e);return i}static findNode(e,t){if(t===void 0||t===""||t==="."||t===-1||t===e.name||t===e.uuid)return e;if(e.skeleton){let i=e.skeleton.getBoneByName(t);if(i!==void 0)return i}if(e.children){let i=function(r){for(let o=0;o<r.length;o++){let a=r[o];if(a.name===t||a.uuid===t)return a;let l=i(a.children);if(l)return l}return null},s=i(e.children);if(s)return s}return null}_getValue_unavailable(){}_setValue_unavailable(){}_getValue_direct(e,t){e[t]=this.targetObject[this.propertyName]}_getValue_array(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)e[t++]=i[s]}_getValue_arrayElement(e,t){e[t]=this.resolvedProperty[this.propertyIndex]}_getValue_toArray(e,t){this.resolvedProperty.toArray(e,t)}_setValue_direct(e,t){this.targetObject[this.propertyName]=e[t]}_setValue_direct_setNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.needsUpdate=!0}_setValue_direct_setMatrixWorldNeedsUpdate(e,t){this.targetObject[this.propertyName]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_array(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)i[s]=e[t++]}_setValue_array_setNeedsUpdate(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)i[s]=e[t++];this.targetObject.needsUpdate=!0}_setValue_array_setMatrixWorldNeedsUpdate(e,t){let i=this.resolvedProperty;for(let s=0,r=i.length;s!==r;++s)i[s]=e[t++];this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_arrayElement(e,t){this.resolvedProperty[this.propertyIndex]=e[t]}_setValue_arrayElement_setNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.needsUpdate=!0}_setValue_arrayElement_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty[this.propertyIndex]=e[t],this.targetObject.matrixWorldNeedsUpdate=!0}_setValue_fromArray(e,t){this.resolvedProperty.fromArray(e,t)}_setValue_fromArray_setNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.needsUpdate=!0}_setValue_fromArray_setMatrixWorldNeedsUpdate(e,t){this.resolvedProperty.fromArray(e,t),this.targetObject.matrixWorldNeedsUpdate=!0}_getValue_unbound(e,t){this.bind(),this.getValue(e,t)}_setValue_unbound(e,t){this.bind(),this.setValue(e,t)}bind(){let e=this.node,t=this.parsedPath,i=t.objectName,s=t.propertyName,r=t.propertyIndex;if(e||(e=n.findNode(this.rootNode,t.nodeName),this.node=e),this.getValue=this._getValue_unavailable,this.setValue=this._setValue_unavailable,!e){Je("PropertyBinding: No target node found for track: "+this.path+".");return}if(i){let c=t.objectIndex;switch(i){case"materials":if(!e.material){rt("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.materials){rt("PropertyBinding: Can not bind to material.materials as node.material does not have a materials array.",this);return}e=e.material.materials;break;case"bones":if(!e.skeleton){rt("PropertyBinding: Can not bind to bones as node does not have a skeleton.",this);return}e=e.skeleton.bones;for(let h=0;h<e.length;h++)if(e[h].name===c){c=h;break}break;case"map":if("map"in e){e=e.map;break}if(!e.material){rt("PropertyBinding: Can not bind to material as node does not have a material.",this);return}if(!e.material.map){rt("PropertyBinding: Can not bind to material.map as node.material does not have a map.",this);return}e=e.material.map;break;default:if(e[i]===void 0){rt("PropertyBinding: Can not bind to objectName of node undefined.",this);return}e=e[i]}if(c!==void 0){if(e[c]===void 0){rt("PropertyBinding: Trying to bind to objectIndex of objectName, but is undefined.",this,e);return}e=e[c]}}let o=e[s];if(o===void 0){let c=t.nodeName;rt("PropertyBinding: Trying to update property for track: "+c+"."+s+" but it wasn't found.",e);return}let a=this.Versioning.None;this.targetObject=e,e.isMaterial===!0?a=this.Versioning.NeedsUpdate:e.isObject3D===!0&&(a=this.Versioning.MatrixWorldNeedsUpdate);let l=this.BindingType.Direct;if(r!==void 0){if(s==="morphTargetInfluences"){if(!e.geometry){rt("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.",this);return}if(!e.geometry.morphAttributes){rt("PropertyBinding: Can not bind to morphTargetInfluences because node does not have a geometry.morphAttributes.",this);return}e.morphTargetDictionary[r]!==void 0&&(r=e.morphTargetDictionary[r])}l=this.BindingType.ArrayElement,this.resolvedProperty=o,this.propertyIndex=r}else o.fromArray!==void 0&&o.toArray!==void 0?(l=this.BindingType.HasFromToArray,this.resolvedProperty=o):Array.isArray(o)?(l=this.BindingType.EntireArray,this.resolvedProperty=o):this.propertyName=s;this.getValue=this.GetterByBindingType[l],this.setValue=this.SetterByBindingTypeAndVersioning[l][a]}unbind(){this.node=null,this.getValue=this._getValue_unbound,this.setValue=this._setValue_unbound}};jt.Composite=Af;jt.prototype.BindingType={Direct:0,EntireArray:1,ArrayElement:2,HasFromToArray:3};jt.prototype.Versioning={None:0,NeedsUpdate:1,MatrixWorldNeedsUpdate:2};jt.prototype.GetterByBindingType=[jt.prototype._getValue_direct,jt.prototype._getValue_array,jt.prototype._getValue_arrayElement,jt.prototype._getValue_toArray];jt.prototype.SetterByBindingTypeAndVersioning=[[jt.prototype._setValue_direct,jt.prototype._setValue_direct_setNeedsUpdate,jt.prototype._setValue_direct_setMatrixWorldNeedsUpdate],[jt.prototype._setValue_array,jt.prototype._setValue_array_setNeedsUpdate,jt.prototype._setValue_array_setMatrixWorldNeedsUpdate],[jt.prototype._setValue_arrayElement,jt.prototype._setValue_arrayElement_setNeedsUpdate,jt.prototype._setValue_arrayElement_setMatrixWorldNeedsUpdate],[jt.prototype._setValue_fromArray,jt.prototype._setValue_fromArray_setNeedsUpdate,jt.prototype._setValue_fromArray_setMatrixWorldNeedsUpdate]];var C1=new Float32Array(1);var Po=class{constructor(e=1,t=0,i=0){this.radius=e,this.phi=t,this.theta=i}set(e,t,i){return this.radius=e,this.phi=t,this.theta=i,this}copy(e){return this.radius=e.radius,this.phi=e.phi,this.theta=e.theta,this}makeSafe(){return this.phi=St(this.phi,1e-6,Math.PI-1e-6),this}setFromVector3(e){return this.setFromCartesianCoords(e.x,e.y,e.z)}setFromCartesianCoords(e,t,i){return this.radius=Math.sqrt(e*e+t*t+i*i),this.radius===0?(this.theta=0,this.phi=0):(this.theta=Math.atan2(e,i),this.phi=Math.acos(St(t/this.radius,-1,1))),this}clone(){return new this.constructor().copy(this)}};var md=class md{constructor(e,t,i,s){this.elements=[1,0,0,1],e!==void 0&&this.set(e,t,i,s)}identity(){return this.set(1,0,0,1),this}fromArray(e,t=0){for(let i=0;i<4;i++)this.elements[i]=e[i+t];return this}set(e,t,i,s){let r=this.elements;return r[0]=e,r[2]=t,r[1]=i,r[3]=s,this}};md.prototype.isMatrix2=!0;var Rf=md;var ka=class extends Pa{constructor(e=10,t=10,i=4473924,s=8947848){i=new gt(i),s=new gt(s);let r=t/2,o=e/t,a=e/2,l=[],c=[];for(let u=0,p=0,g=-a;u<=t;u++,g+=o){l.push(-a,0,g,a,0,g),l.push(g,0,-a,g,0,a);let S=u===r?i:s;S.toArray(c,p),p+=3,S.toArray(c,p),p+=3,S.toArray(c,p),p+=3,S.toArray(c,p),p+=3}let h=new jn;h.setAttribute("position",new Pn(l,3)),h.setAttribute("color",new Pn(c,3));let f=new Ao({vertexColors:!0,toneMapped:!1});super(h,f),this.type="GridHelper"}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}};var za=class extends Pa{constructor(e=1){let t=[0,0,0,e,0,0,0,0,0,0,e,0,0,0,0,0,0,e],i=[1,0,0,1,.6,0,0,1,0,.6,1,0,0,0,1,0,.6,1],s=new jn;s.setAttribute("position",new Pn(t,3)),s.setAttribute("color",new Pn(i,3));let r=new Ao({vertexColors:!0,toneMapped:!1});super(s,r),this.type="AxesHelper"}setColors(e,t,i){let s=new gt,r=this.geometry.attributes.color.array;return s.set(e),s.toArray(r,0),s.toArray(r,3),s.set(t),s.toArray(r,6),s.toArray(r,9),s.set(i),s.toArray(r,12),s.toArray(r,15),this.geometry.attributes.color.needsUpdate=!0,this}dispose(){super.dispose(),this.geometry.dispose(),this.material.dispose()}};var Ga=class extends Di{constructor(e,t=null){super(),this.object=e,this.domElement=t,this.enabled=!0,this.state=-1,this.keys={},this.mouseButtons={LEFT:null,MIDDLE:null,RIGHT:null},this.touches={ONE:null,TWO:null}}connect(e){this.domElement!==null&&this.disconnect(),this.domElement=e}disconnect(){}dispose(){}update(){}};function hd(n,e,t,i){let s=Jv(i);switch(t){case $f:return n*e;case Kf:return n*e/s.components*s.byteLength;case th:return n*e/s.components*s.byteLength;case or:return n*e*2/s.components*s.byteLength;case nh:return n*e*2/s.components*s.byteLength;case Zf:return n*e*3/s.components*s.byteLength;case Bi:return n*e*4/s.components*s.byteLength;case ih:return n*e*4/s.components*s.byteLength;case Wa:case Xa:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case qa:case Ya:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case rh:case ah:return Math.max(n,16)*Math.max(e,8)/4;case sh:case oh:return Math.max(n,8)*Math.max(e,8)/2;case lh:case ch:case uh:case fh:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*8;case hh:case $a:case dh:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case ph:return Math.floor((n+3)/4)*Math.floor((e+3)/4)*16;case mh:return Math.floor((n+4)/5)*Math.floor((e+3)/4)*16;case gh:return Math.floor((n+4)/5)*Math.floor((e+4)/5)*16;case _h:return Math.floor((n+5)/6)*Math.floor((e+4)/5)*16;case xh:return Math.floor((n+5)/6)*Math.floor((e+5)/6)*16;case yh:return Math.floor((n+7)/8)*Math.floor((e+4)/5)*16;case vh:return Math.floor((n+7)/8)*Math.floor((e+5)/6)*16;case Sh:return Math.floor((n+7)/8)*Math.floor((e+7)/8)*16;case bh:return Math.floor((n+9)/10)*Math.floor((e+4)/5)*16;case Mh:return Math.floor((n+9)/10)*Math.floor((e+5)/6)*16;case wh:return Math.floor((n+9)/10)*Math.floor((e+7)/8)*16;case Eh:return Math.floor((n+9)/10)*Math.floor((e+9)/10)*16;case Th:return Math.floor((n+11)/12)*Math.floor((e+9)/10)*16;case Ah:return Math.floor((n+11)/12)*Math.floor((e+11)/12)*16;case Rh:case Ch:case Ih:return Math.ceil(n/4)*Math.ceil(e/4)*16;case Ph:case Lh:return Math.ceil(n/4)*Math.ceil(e/4)*8;case Za:case Nh:return Math.ceil(n/4)*Math.ceil(e/4)*16}throw new Error(`Unable to determine texture byte length for ${t} format.`)}function Jv(n){switch(n){case gi:case Wf:return{byteLength:1,components:1};case Uo:case Xf:case Fi:return{byteLength:2,components:1};case Qc:case eh:return{byteLength:2,components:4};case Ui:case jc:case Oi:return{byteLength:4,components:1};case qf:case Yf:return{byteLength:4,components:3}}throw new Error(`THREE.TextureUtils: Unknown texture type ${n}.`)}typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("register",{detail:{revision:"187"}}));typeof window<"u"&&(window.__THREE__?Je("WARNING: Multiple instances of Three.js being imported."):window.__THREE__="187");function j0(){let n=null,e=!1,t=null,i=null;function s(r,o){i=n.requestAnimationFrame(s),t(r,o)}return{start:function(){e!==!0&&t!==null&&n!==null&&(i=n.requestAnimationFrame(s),e=!0)},stop:function(){n!==null&&n.cancelAnimationFrame(i),e=!1},setAnimationLoop:function(r){t=r},setContext:function(r){n=r}}}function Qv(n){let e=new WeakMap;function t(a,l){let c=a.array,h=a.usage,f=c.byteLength,u=n.createBuffer();n.bindBuffer(l,u),n.bufferData(l,c,h),a.onUploadCallback();let p;if(c instanceof Float32Array)p=n.FLOAT;else if(typeof Float16Array<"u"&&c instanceof Float16Array)p=n.HALF_FLOAT;else if(c instanceof Uint16Array)a.isFloat16BufferAttribute?p=n.HALF_FLOAT:p=n.UNSIGNED_SHORT;else if(c instanceof Int16Array)p=n.SHORT;else if(c instanceof Uint32Array)p=n.UNSIGNED_INT;else if(c instanceof Int32Array)p=n.INT;else if(c instanceof Int8Array)p=n.BYTE;else if(c instanceof Uint8Array)p=n.UNSIGNED_BYTE;else if(c instanceof Uint8ClampedArray)p=n.UNSIGNED_BYTE;else throw new Error("THREE.WebGLAttributes: Unsupported buffer data format: "+c);return{buffer:u,type:p,bytesPerElement:c.BYTES_PER_ELEMENT,version:a.version,size:f}}function i(a,l,c){let h=l.array,f=l.updateRanges;if(n.bindBuffer(c,a),f.length===0)n.bufferSubData(c,0,h);else{f.sort((p,g)=>p.start-g.start);let u=0;for(let p=1;p<f.length;p++){let g=f[u],S=f[p];S.start<=g.start+g.count+1?g.count=Math.max(g.count,S.start+S.count-g.start):(++u,f[u]=S)}f.length=u+1;for(let p=0,g=f.length;p<g;p++){let S=f[p];n.bufferSubData(c,S.start*h.BYTES_PER_ELEMENT,h,S.start,S.count)}l.clearUpdateRanges()}l.onUploadCallback()}function s(a){return a.isInterleavedBufferAttribute&&(a=a.data),e.get(a)}function r(a){a.isInterleavedBufferAttribute&&(a=a.data);let l=e.get(a);l&&(n.deleteBuffer(l.buffer),e.delete(a))}function o(a,l){if(a.isInterleavedBufferAttribute&&(a=a.data),a.isGLBufferAttribute){let h=e.get(a);(!h||h.version<a.version)&&e.set(a,{buffer:a.buffer,type:a.type,bytesPerElement:a.elementSize,version:a.version});return}let c=e.get(a);if(c===void 0)e.set(a,t(a,l));else if(c.version<a.version){if(c.size!==a.array.byteLength)throw new Error("THREE.WebGLAttributes: The size of the buffer attribute's array buffer does not match the original size. Resizing buffer attributes is not supported.");i(c.buffer,a,l),c.version=a.version}}return{get:s,remove:r,update:o}}var eS=`#ifdef USE_ALPHAHASH
	if ( diffuseColor.a < getAlphaHashThreshold( vPosition ) ) discard;
#endif`,tS=`#ifdef USE_ALPHAHASH
	const float ALPHA_HASH_SCALE = 0.05;
	float hash2D( vec2 value ) {
		return fract( 1.0e4 * sin( 17.0 * value.x + 0.1 * value.y ) * ( 0.1 + abs( sin( 13.0 * value.y + value.x ) ) ) );
	}
	float hash3D( vec3 value ) {
		return hash2D( vec2( hash2D( value.xy ), value.z ) );
	}
	float getAlphaHashThreshold( vec3 position ) {
		float maxDeriv = max(
			length( dFdx( position.xyz ) ),
			length( dFdy( position.xyz ) )
		);
		float pixScale = 1.0 / ( ALPHA_HASH_SCALE * maxDeriv );
		vec2 pixScales = vec2(
			exp2( floor( log2( pixScale ) ) ),
			exp2( ceil( log2( pixScale ) ) )
		);
		vec2 alpha = vec2(
			hash3D( floor( pixScales.x * position.xyz ) ),
			hash3D( floor( pixScales.y * position.xyz ) )
		);
		float lerpFactor = fract( log2( pixScale ) );
		float x = ( 1.0 - lerpFactor ) * alpha.x + lerpFactor * alpha.y;
		float a = min( lerpFactor, 1.0 - lerpFactor );
		vec3 cases = vec3(
			x * x / ( 2.0 * a * ( 1.0 - a ) ),
			( x - 0.5 * a ) / ( 1.0 - a ),
			1.0 - ( ( 1.0 - x ) * ( 1.0 - x ) / ( 2.0 * a * ( 1.0 - a ) ) )
		);
		float threshold = ( x < ( 1.0 - a ) )
			? ( ( x < a ) ? cases.x : cases.y )
			: cases.z;
		return clamp( threshold , 1.0e-6, 1.0 );
	}
#endif`,nS=`#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, vAlphaMapUv ).g;
#endif`,iS=`#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,sS=`#ifdef USE_ALPHATEST
	#ifdef ALPHA_TO_COVERAGE
	diffuseColor.a = smoothstep( alphaTest, alphaTest + fwidth( diffuseColor.a ), diffuseColor.a );
	if ( diffuseColor.a == 0.0 ) discard;
	#else
	if ( diffuseColor.a < alphaTest ) discard;
	#endif
#endif`,rS=`#ifdef USE_ALPHATEST
	uniform float alphaTest;
#endif`,oS=`#ifdef USE_AOMAP
	float ambientOcclusion = ( texture2D( aoMap, vAoMapUv ).r - 1.0 ) * aoMapIntensity + 1.0;
	reflectedLight.indirectDiffuse *= ambientOcclusion;
	#if defined( USE_CLEARCOAT ) 
		clearcoatSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_SHEEN ) 
		sheenSpecularIndirect *= ambientOcclusion;
	#endif
	#if defined( USE_ENVMAP ) && defined( STANDARD )
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		reflectedLight.indirectSpecular *= computeSpecularOcclusion( dotNV, ambientOcclusion, material.roughness );
	#endif
#endif`,aS=`#ifdef USE_AOMAP
	uniform sampler2D aoMap;
	uniform float aoMapIntensity;
#endif`,lS=`#ifdef USE_BATCHING
	#if ! defined( GL_ANGLE_multi_draw )
	#define gl_DrawID _gl_DrawID
	uniform int _gl_DrawID;
	#endif
	uniform highp sampler2D batchingTexture;
	uniform highp usampler2D batchingIdTexture;
	mat4 getBatchingMatrix( const in float i ) {
		int size = textureSize( batchingTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( batchingTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( batchingTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( batchingTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( batchingTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
	float getIndirectIndex( const in int i ) {
		int size = textureSize( batchingIdTexture, 0 ).x;
		int x = i % size;
		int y = i / size;
		return float( texelFetch( batchingIdTexture, ivec2( x, y ), 0 ).r );
	}
#endif
#ifdef USE_BATCHING_COLOR
	uniform sampler2D batchingColorTexture;
	vec4 getBatchingColor( const in float i ) {
		int size = textureSize( batchingColorTexture, 0 ).x;
		int j = int( i );
		int x = j % size;
		int y = j / size;
		return texelFetch( batchingColorTexture, ivec2( x, y ), 0 );
	}
#endif`,cS=`#ifdef USE_BATCHING
	mat4 batchingMatrix = getBatchingMatrix( getIndirectIndex( gl_DrawID ) );
#endif`,hS=`vec3 transformed = vec3( position );
#ifdef USE_ALPHAHASH
	vPosition = vec3( position );
#endif`,uS=`vec3 objectNormal = vec3( normal );
#ifdef USE_TANGENT
	vec3 objectTangent = vec3( tangent.xyz );
#endif`,fS=`float G_BlinnPhong_Implicit( ) {
	return 0.25;
}
float D_BlinnPhong( const in float shininess, const in float dotNH ) {
	return RECIPROCAL_PI * ( shininess * 0.5 + 1.0 ) * pow( dotNH, shininess );
}
vec3 BRDF_BlinnPhong( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 specularColor, const in float shininess ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( specularColor, 1.0, dotVH );
	float G = G_BlinnPhong_Implicit( );
	float D = D_BlinnPhong( shininess, dotNH );
	return F * ( G * D );
} // validated`,dS=`#ifdef USE_IRIDESCENCE
	const mat3 XYZ_TO_REC709 = mat3(
		 3.2404542, -0.9692660,  0.0556434,
		-1.5371385,  1.8760108, -0.2040259,
		-0.4985314,  0.0415560,  1.0572252
	);
	vec3 Fresnel0ToIor( vec3 fresnel0 ) {
		vec3 sqrtF0 = sqrt( fresnel0 );
		return ( vec3( 1.0 ) + sqrtF0 ) / ( vec3( 1.0 ) - sqrtF0 );
	}
	vec3 IorToFresnel0( vec3 transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - vec3( incidentIor ) ) / ( transmittedIor + vec3( incidentIor ) ) );
	}
	float IorToFresnel0( float transmittedIor, float incidentIor ) {
		return pow2( ( transmittedIor - incidentIor ) / ( transmittedIor + incidentIor ));
	}
	vec3 evalSensitivity( float OPD, vec3 shift ) {
		float phase = 2.0 * PI * OPD * 1.0e-9;
		vec3 val = vec3( 5.4856e-13, 4.4201e-13, 5.2481e-13 );
		vec3 pos = vec3( 1.6810e+06, 1.7953e+06, 2.2084e+06 );
		vec3 var = vec3( 4.3278e+09, 9.3046e+09, 6.6121e+09 );
		vec3 xyz = val * sqrt( 2.0 * PI * var ) * cos( pos * phase + shift ) * exp( - pow2( phase ) * var );
		xyz.x += 9.7470e-14 * sqrt( 2.0 * PI * 4.5282e+09 ) * cos( 2.2399e+06 * phase + shift[ 0 ] ) * exp( - 4.5282e+09 * pow2( phase ) );
		xyz /= 1.0685e-7;
		vec3 rgb = XYZ_TO_REC709 * xyz;
		return rgb;
	}
	vec3 evalIridescence( float outsideIOR, float eta2, float cosTheta1, float thinFilmThickness, vec3 baseF0 ) {
		vec3 I;
		float iridescenceIOR = mix( outsideIOR, eta2, smoothstep( 0.0, 0.03, thinFilmThickness ) );
		float sinTheta2Sq = pow2( outsideIOR / iridescenceIOR ) * ( 1.0 - pow2( cosTheta1 ) );
		float cosTheta2Sq = 1.0 - sinTheta2Sq;
		if ( cosTheta2Sq < 0.0 ) {
			return vec3( 1.0 );
		}
		float cosTheta2 = sqrt( cosTheta2Sq );
		float R0 = IorToFresnel0( iridescenceIOR, outsideIOR );
		float R12 = F_Schlick( R0, 1.0, cosTheta1 );
		float T121 = 1.0 - R12;
		float phi12 = 0.0;
		if ( iridescenceIOR < outsideIOR ) phi12 = PI;
		float phi21 = PI - phi12;
		vec3 baseIOR = Fresnel0ToIor( clamp( baseF0, 0.0, 0.9999 ) );		vec3 R1 = IorToFresnel0( baseIOR, iridescenceIOR );
		vec3 R23 = F_Schlick( R1, 1.0, cosTheta2 );
		vec3 phi23 = vec3( 0.0 );
		if ( baseIOR[ 0 ] < iridescenceIOR ) phi23[ 0 ] = PI;
		if ( baseIOR[ 1 ] < iridescenceIOR ) phi23[ 1 ] = PI;
		if ( baseIOR[ 2 ] < iridescenceIOR ) phi23[ 2 ] = PI;
		float OPD = 2.0 * iridescenceIOR * thinFilmThickness * cosTheta2;
		vec3 phi = vec3( phi21 ) + phi23;
		vec3 R123 = clamp( R12 * R23, 1e-5, 0.9999 );
		vec3 r123 = sqrt( R123 );
		vec3 Rs = pow2( T121 ) * R23 / ( vec3( 1.0 ) - R123 );
		vec3 C0 = R12 + Rs;
		I = C0;
		vec3 Cm = Rs - T121;
		for ( int m = 1; m <= 2; ++ m ) {
			Cm *= r123;
			vec3 Sm = 2.0 * evalSensitivity( float( m ) * OPD, float( m ) * phi );
			I += Cm * Sm;
		}
		return max( I, vec3( 0.0 ) );
	}
#endif`,pS=`#ifdef USE_BUMPMAP
	uniform sampler2D bumpMap;
	uniform float bumpScale;
	vec2 dHdxy_fwd() {
		vec2 dSTdx = dFdx( vBumpMapUv );
		vec2 dSTdy = dFdy( vBumpMapUv );
		float Hll = bumpScale * texture2D( bumpMap, vBumpMapUv ).x;
		float dBx = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdx ).x - Hll;
		float dBy = bumpScale * texture2D( bumpMap, vBumpMapUv + dSTdy ).x - Hll;
		return vec2( dBx, dBy );
	}
	vec3 perturbNormalArb( vec3 surf_pos, vec3 surf_norm, vec2 dHdxy, float faceDirection ) {
		vec3 vSigmaX = normalize( dFdx( surf_pos.xyz ) );
		vec3 vSigmaY = normalize( dFdy( surf_pos.xyz ) );
		vec3 vN = surf_norm;
		vec3 R1 = cross( vSigmaY, vN );
		vec3 R2 = cross( vN, vSigmaX );
		float fDet = dot( vSigmaX, R1 ) * faceDirection;
		vec3 vGrad = sign( fDet ) * ( dHdxy.x * R1 + dHdxy.y * R2 );
		return normalize( abs( fDet ) * surf_norm - vGrad );
	}
#endif`,mS=`#if NUM_CLIPPING_PLANES > 0
	vec4 plane;
	#ifdef ALPHA_TO_COVERAGE
		float distanceToPlane, distanceGradient;
		float clipOpacity = 1.0;
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
			distanceGradient = fwidth( distanceToPlane ) / 2.0;
			clipOpacity *= smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			if ( clipOpacity == 0.0 ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			float unionClipOpacity = 1.0;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				distanceToPlane = - dot( vClipPosition, plane.xyz ) + plane.w;
				distanceGradient = fwidth( distanceToPlane ) / 2.0;
				unionClipOpacity *= 1.0 - smoothstep( - distanceGradient, distanceGradient, distanceToPlane );
			}
			#pragma unroll_loop_end
			clipOpacity *= 1.0 - unionClipOpacity;
		#endif
		diffuseColor.a *= clipOpacity;
		if ( diffuseColor.a == 0.0 ) discard;
	#else
		#pragma unroll_loop_start
		for ( int i = 0; i < UNION_CLIPPING_PLANES; i ++ ) {
			plane = clippingPlanes[ i ];
			if ( dot( vClipPosition, plane.xyz ) > plane.w ) discard;
		}
		#pragma unroll_loop_end
		#if UNION_CLIPPING_PLANES < NUM_CLIPPING_PLANES
			bool clipped = true;
			#pragma unroll_loop_start
			for ( int i = UNION_CLIPPING_PLANES; i < NUM_CLIPPING_PLANES; i ++ ) {
				plane = clippingPlanes[ i ];
				clipped = ( dot( vClipPosition, plane.xyz ) > plane.w ) && clipped;
			}
			#pragma unroll_loop_end
			if ( clipped ) discard;
		#endif
	#endif
#endif`,gS=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
	uniform vec4 clippingPlanes[ NUM_CLIPPING_PLANES ];
#endif`,_S=`#if NUM_CLIPPING_PLANES > 0
	varying vec3 vClipPosition;
#endif`,xS=`#if NUM_CLIPPING_PLANES > 0
	vClipPosition = - mvPosition.xyz;
#endif`,yS=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	diffuseColor *= vColor;
#endif`,vS=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA )
	varying vec4 vColor;
#endif`,SS=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	varying vec4 vColor;
#endif`,bS=`#if defined( USE_COLOR ) || defined( USE_COLOR_ALPHA ) || defined( USE_INSTANCING_COLOR ) || defined( USE_BATCHING_COLOR )
	vColor = vec4( 1.0 );
#endif
#ifdef USE_COLOR_ALPHA
	vColor *= color;
#elif defined( USE_COLOR )
	vColor.rgb *= color;
#endif
#ifdef USE_INSTANCING_COLOR
	vColor.rgb *= instanceColor.rgb;
#endif
#ifdef USE_BATCHING_COLOR
	vColor *= getBatchingColor( getIndirectIndex( gl_DrawID ) );
#endif`,MS=`#define PI 3.141592653589793
#define PI2 6.283185307179586
#define PI_HALF 1.5707963267948966
#define RECIPROCAL_PI 0.3183098861837907
#define RECIPROCAL_PI2 0.15915494309189535
#define EPSILON 1e-6
#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
#define whiteComplement( a ) ( 1.0 - saturate( a ) )
float pow2( const in float x ) { return x*x; }
vec3 pow2( const in vec3 x ) { return x*x; }
float pow3( const in float x ) { return x*x*x; }
float pow4( const in float x ) { float x2 = x*x; return x2*x2; }
float max3( const in vec3 v ) { return max( max( v.x, v.y ), v.z ); }
float average( const in vec3 v ) { return dot( v, vec3( 0.3333333 ) ); }
highp float rand( const in vec2 uv ) {
	const highp float a = 12.9898, b = 78.233, c = 43758.5453;
	highp float dt = dot( uv.xy, vec2( a,b ) ), sn = mod( dt, PI );
	return fract( sin( sn ) * c );
}
#ifdef HIGH_PRECISION
	float precisionSafeLength( vec3 v ) { return length( v ); }
#else
	float precisionSafeLength( vec3 v ) {
		float maxComponent = max3( abs( v ) );
		return length( v / maxComponent ) * maxComponent;
	}
#endif
struct IncidentLight {
	vec3 color;
	vec3 direction;
	bool visible;
};
struct ReflectedLight {
	vec3 directDiffuse;
	vec3 directSpecular;
	vec3 indirectDiffuse;
	vec3 indirectSpecular;
};
#ifdef USE_ALPHAHASH
	varying vec3 vPosition;
#endif
vec3 transformDirection( in vec3 dir, in mat4 matrix ) {
	return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );
}
#define inverseTransformDirection transformDirectionByInverseViewMatrix
vec3 transformNormalByInverseViewMatrix( in vec3 normal, in mat4 viewMatrix ) {
	return normalize( ( vec4( normal, 0.0 ) * viewMatrix ).xyz );
}
vec3 transformDirectionByInverseViewMatrix( in vec3 dir, in mat4 viewMatrix ) {
	return normalize( ( vec4( dir, 0.0 ) * viewMatrix ).xyz );
}
bool isPerspectiveMatrix( mat4 m ) {
	return m[ 2 ][ 3 ] == - 1.0;
}
vec2 equirectUv( in vec3 dir ) {
	float u = atan( dir.z, dir.x ) * RECIPROCAL_PI2 + 0.5;
	float v = asin( clamp( dir.y, - 1.0, 1.0 ) ) * RECIPROCAL_PI + 0.5;
	return vec2( u, v );
}
vec3 BRDF_Lambert( const in vec3 diffuseColor ) {
	return RECIPROCAL_PI * diffuseColor;
}
vec3 F_Schlick( const in vec3 f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
}
float F_Schlick( const in float f0, const in float f90, const in float dotVH ) {
	float fresnel = exp2( ( - 5.55473 * dotVH - 6.98316 ) * dotVH );
	return f0 * ( 1.0 - fresnel ) + ( f90 * fresnel );
} // validated`,wS=`vec3 transformedNormal = objectNormal;
#ifdef USE_TANGENT
	vec3 transformedTangent = objectTangent;
#endif
#ifdef USE_BATCHING
	mat3 bm = mat3( batchingMatrix );
	transformedNormal /= vec3( dot( bm[ 0 ], bm[ 0 ] ), dot( bm[ 1 ], bm[ 1 ] ), dot( bm[ 2 ], bm[ 2 ] ) );
	transformedNormal = bm * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = bm * transformedTangent;
	#endif
#endif
#ifdef USE_INSTANCING
	mat3 im = mat3( instanceMatrix );
	transformedNormal /= vec3( dot( im[ 0 ], im[ 0 ] ), dot( im[ 1 ], im[ 1 ] ), dot( im[ 2 ], im[ 2 ] ) );
	transformedNormal = im * transformedNormal;
	#ifdef USE_TANGENT
		transformedTangent = im * transformedTangent;
	#endif
#endif
transformedNormal = normalMatrix * transformedNormal;
#ifdef FLIP_SIDED
	transformedNormal = - transformedNormal;
#endif
#ifdef USE_TANGENT
	transformedTangent = ( modelViewMatrix * vec4( transformedTangent, 0.0 ) ).xyz;
#endif`,ES=`#ifdef USE_DISPLACEMENTMAP
	uniform sampler2D displacementMap;
	uniform float displacementScale;
	uniform float displacementBias;
#endif`,TS=`#ifdef USE_DISPLACEMENTMAP
	transformed += normalize( objectNormal ) * ( texture2D( displacementMap, vDisplacementMapUv ).x * displacementScale + displacementBias );
#endif`,AS=`#ifdef USE_EMISSIVEMAP
	vec4 emissiveColor = texture2D( emissiveMap, vEmissiveMapUv );
	#ifdef DECODE_VIDEO_TEXTURE_EMISSIVE
		emissiveColor = sRGBTransferEOTF( emissiveColor );
	#endif
	totalEmissiveRadiance *= emissiveColor.rgb;
#endif`,RS=`#ifdef USE_EMISSIVEMAP
	uniform sampler2D emissiveMap;
#endif`,CS="gl_FragColor = linearToOutputTexel( gl_FragColor );",IS=`vec4 LinearTransferOETF( in vec4 value ) {
	return value;
}
vec4 sRGBTransferEOTF( in vec4 value ) {
	return vec4( mix( pow( value.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), value.rgb * 0.0773993808, vec3( lessThanEqual( value.rgb, vec3( 0.04045 ) ) ) ), value.a );
}
vec4 sRGBTransferOETF( in vec4 value ) {
	return vec4( mix( pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 ), value.rgb * 12.92, vec3( lessThanEqual( value.rgb, vec3( 0.0031308 ) ) ) ), value.a );
}`,PS=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vec3 cameraToFrag;
		if ( isOrthographic ) {
			cameraToFrag = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToFrag = normalize( vWorldPosition - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vec3 reflectVec = reflect( cameraToFrag, worldNormal );
		#else
			vec3 reflectVec = refract( cameraToFrag, worldNormal, refractionRatio );
		#endif
	#else
		vec3 reflectVec = vReflect;
	#endif
	#ifdef ENVMAP_TYPE_CUBE
		vec4 envColor = textureCube( envMap, envMapRotation * reflectVec );
		#ifdef ENVMAP_BLENDING_MULTIPLY
			outgoingLight = mix( outgoingLight, outgoingLight * envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_MIX )
			outgoingLight = mix( outgoingLight, envColor.xyz, specularStrength * reflectivity );
		#elif defined( ENVMAP_BLENDING_ADD )
			outgoingLight += envColor.xyz * specularStrength * reflectivity;
		#endif
	#endif
#endif`,LS=`#ifdef USE_ENVMAP
	uniform float envMapIntensity;
	uniform mat3 envMapRotation;
	uniform samplerCube envMap;
	#ifdef ENVMAP_TYPE_PMREM
		float roughnessToMip( const in float roughness ) {
			float r = clamp( roughness, 0.0, 1.0 );
			return ENVMAP_MAX_LOD * r * ( 2.0 - r );
		}
	#endif
#endif`,NS=`#ifdef USE_ENVMAP
	uniform float reflectivity;
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		varying vec3 vWorldPosition;
		uniform float refractionRatio;
	#else
		varying vec3 vReflect;
	#endif
#endif`,DS=`#ifdef USE_ENVMAP
	#if defined( USE_BUMPMAP ) || defined( USE_NORMALMAP ) || defined( PHONG ) || defined( LAMBERT )
		#define ENV_WORLDPOS
	#endif
	#ifdef ENV_WORLDPOS
		
		varying vec3 vWorldPosition;
	#else
		varying vec3 vReflect;
		uniform float refractionRatio;
	#endif
#endif`,US=`#ifdef USE_ENVMAP
	#ifdef ENV_WORLDPOS
		vWorldPosition = worldPosition.xyz;
	#else
		vec3 cameraToVertex;
		if ( isOrthographic ) {
			cameraToVertex = normalize( vec3( - viewMatrix[ 0 ][ 2 ], - viewMatrix[ 1 ][ 2 ], - viewMatrix[ 2 ][ 2 ] ) );
		} else {
			cameraToVertex = normalize( worldPosition.xyz - cameraPosition );
		}
		vec3 worldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
		#ifdef ENVMAP_MODE_REFLECTION
			vReflect = reflect( cameraToVertex, worldNormal );
		#else
			vReflect = refract( cameraToVertex, worldNormal, refractionRatio );
		#endif
	#endif
#endif`,OS=`#ifdef USE_FOG
	vFogDepth = - mvPosition.z;
#endif`,FS=`#ifdef USE_FOG
	varying float vFogDepth;
#endif`,BS=`#ifdef USE_FOG
	#ifdef FOG_EXP2
		float fogFactor = 1.0 - exp( - fogDensity * fogDensity * vFogDepth * vFogDepth );
	#else
		float fogFactor = smoothstep( fogNear, fogFar, vFogDepth );
	#endif
	gl_FragColor.rgb = mix( gl_FragColor.rgb, fogColor, fogFactor );
#endif`,kS=`#ifdef USE_FOG
	uniform vec3 fogColor;
	varying float vFogDepth;
	#ifdef FOG_EXP2
		uniform float fogDensity;
	#else
		uniform float fogNear;
		uniform float fogFar;
	#endif
#endif`,zS=`#ifdef USE_GRADIENTMAP
	uniform sampler2D gradientMap;
#endif
vec3 getGradientIrradiance( vec3 normal, vec3 lightDirection ) {
	float dotNL = dot( normal, lightDirection );
	vec2 coord = vec2( dotNL * 0.5 + 0.5, 0.0 );
	#ifdef USE_GRADIENTMAP
		return vec3( texture2D( gradientMap, coord ).r );
	#else
		vec2 fw = fwidth( coord ) * 0.5;
		return mix( vec3( 0.7 ), vec3( 1.0 ), smoothstep( 0.7 - fw.x, 0.7 + fw.x, coord.x ) );
	#endif
}`,GS=`#ifdef USE_LIGHTMAP
	uniform sampler2D lightMap;
	uniform float lightMapIntensity;
#endif`,HS=`LambertMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularStrength = specularStrength;`,VS=`varying vec3 vViewPosition;
struct LambertMaterial {
	vec3 diffuseColor;
	float specularStrength;
};
void RE_Direct_Lambert( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Lambert( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in LambertMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Lambert
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Lambert`,WS=`uniform bool receiveShadow;
uniform vec3 ambientLightColor;
#if defined( USE_LIGHT_PROBES )
	uniform vec3 lightProbe[ 9 ];
#endif
vec3 shGetIrradianceAt( in vec3 normal, in vec3 shCoefficients[ 9 ] ) {
	float x = normal.x, y = normal.y, z = normal.z;
	vec3 result = shCoefficients[ 0 ] * 0.886227;
	result += shCoefficients[ 1 ] * 2.0 * 0.511664 * y;
	result += shCoefficients[ 2 ] * 2.0 * 0.511664 * z;
	result += shCoefficients[ 3 ] * 2.0 * 0.511664 * x;
	result += shCoefficients[ 4 ] * 2.0 * 0.429043 * x * y;
	result += shCoefficients[ 5 ] * 2.0 * 0.429043 * y * z;
	result += shCoefficients[ 6 ] * ( 0.743125 * z * z - 0.247708 );
	result += shCoefficients[ 7 ] * 2.0 * 0.429043 * x * z;
	result += shCoefficients[ 8 ] * 0.429043 * ( x * x - y * y );
	return result;
}
vec3 getLightProbeIrradiance( const in vec3 lightProbe[ 9 ], const in vec3 normal ) {
	vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec3 irradiance = shGetIrradianceAt( worldNormal, lightProbe );
	return irradiance;
}
vec3 getAmbientLightIrradiance( const in vec3 ambientLightColor ) {
	vec3 irradiance = ambientLightColor;
	return irradiance;
}
float getDistanceAttenuation( const in float lightDistance, const in float cutoffDistance, const in float decayExponent ) {
	float distanceFalloff = 1.0 / max( pow( lightDistance, decayExponent ), 0.01 );
	if ( cutoffDistance > 0.0 ) {
		distanceFalloff *= pow2( saturate( 1.0 - pow4( lightDistance / cutoffDistance ) ) );
	}
	return distanceFalloff;
}
float getSpotAttenuation( const in float coneCosine, const in float penumbraCosine, const in float angleCosine ) {
	return smoothstep( coneCosine, penumbraCosine, angleCosine );
}
#if NUM_SUN_LIGHTS > 0
	struct SunLight {
		vec3 direction;
		vec3 color;
	};
	uniform SunLight sunLights[ NUM_SUN_LIGHTS ];
	void getSunLightInfo( const in SunLight sunLight, out IncidentLight light ) {
		light.color = sunLight.color;
		light.direction = sunLight.direction;
		light.visible = true;
	}
#endif
#if NUM_DIR_LIGHTS > 0
	struct DirectionalLight {
		vec3 direction;
		vec3 color;
	};
	uniform DirectionalLight directionalLights[ NUM_DIR_LIGHTS ];
	void getDirectionalLightInfo( const in DirectionalLight directionalLight, out IncidentLight light ) {
		light.color = directionalLight.color;
		light.direction = directionalLight.direction;
		light.visible = true;
	}
#endif
#if NUM_POINT_LIGHTS > 0
	struct PointLight {
		vec3 position;
		vec3 color;
		float distance;
		float decay;
	};
	uniform PointLight pointLights[ NUM_POINT_LIGHTS ];
	void getPointLightInfo( const in PointLight pointLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = pointLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float lightDistance = length( lVector );
		light.color = pointLight.color;
		light.color *= getDistanceAttenuation( lightDistance, pointLight.distance, pointLight.decay );
		light.visible = ( light.color != vec3( 0.0 ) );
	}
#endif
#if NUM_SPOT_LIGHTS > 0
	struct SpotLight {
		vec3 position;
		vec3 direction;
		vec3 color;
		float distance;
		float decay;
		float coneCos;
		float penumbraCos;
	};
	uniform SpotLight spotLights[ NUM_SPOT_LIGHTS ];
	void getSpotLightInfo( const in SpotLight spotLight, const in vec3 geometryPosition, out IncidentLight light ) {
		vec3 lVector = spotLight.position - geometryPosition;
		light.direction = normalize( lVector );
		float angleCos = dot( light.direction, spotLight.direction );
		float spotAttenuation = getSpotAttenuation( spotLight.coneCos, spotLight.penumbraCos, angleCos );
		if ( spotAttenuation > 0.0 ) {
			float lightDistance = length( lVector );
			light.color = spotLight.color * spotAttenuation;
			light.color *= getDistanceAttenuation( lightDistance, spotLight.distance, spotLight.decay );
			light.visible = ( light.color != vec3( 0.0 ) );
		} else {
			light.color = vec3( 0.0 );
			light.visible = false;
		}
	}
#endif
#if NUM_RECT_AREA_LIGHTS > 0
	struct RectAreaLight {
		vec3 color;
		vec3 position;
		vec3 halfWidth;
		vec3 halfHeight;
	};
	uniform sampler2D ltc_1;	uniform sampler2D ltc_2;
	uniform RectAreaLight rectAreaLights[ NUM_RECT_AREA_LIGHTS ];
#endif
#if NUM_HEMI_LIGHTS > 0
	struct HemisphereLight {
		vec3 direction;
		vec3 skyColor;
		vec3 groundColor;
	};
	uniform HemisphereLight hemisphereLights[ NUM_HEMI_LIGHTS ];
	vec3 getHemisphereLightIrradiance( const in HemisphereLight hemiLight, const in vec3 normal ) {
		float dotNL = dot( normal, hemiLight.direction );
		float hemiDiffuseWeight = 0.5 * dotNL + 0.5;
		vec3 irradiance = mix( hemiLight.groundColor, hemiLight.skyColor, hemiDiffuseWeight );
		return irradiance;
	}
#endif
#include <lightprobes_pars_fragment>`,XS=`#ifdef USE_ENVMAP
	vec3 getIBLIrradiance( const in vec3 normal ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 worldNormal = transformNormalByInverseViewMatrix( normal, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * worldNormal, ENVMAP_MAX_LOD );
			return PI * envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	vec3 getIBLRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
		#ifdef ENVMAP_TYPE_PMREM
			vec3 reflectVec = reflect( - viewDir, normal );
			reflectVec = normalize( mix( reflectVec, normal, pow4( roughness ) ) );
			reflectVec = transformDirectionByInverseViewMatrix( reflectVec, viewMatrix );
			vec4 envMapColor = textureLod( envMap, envMapRotation * reflectVec, roughnessToMip( roughness ) );
			return envMapColor.rgb * envMapIntensity;
		#else
			return vec3( 0.0 );
		#endif
	}
	#ifdef USE_RETROREFLECTION
		vec3 getIBLRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 retroVec = normalize( mix( viewDir, normal, pow4( roughness ) ) );
				retroVec = transformDirectionByInverseViewMatrix( retroVec, viewMatrix );
				vec4 envMapColor = textureLod( envMap, envMapRotation * retroVec, roughnessToMip( roughness ) );
				return envMapColor.rgb * envMapIntensity;
			#else
				return vec3( 0.0 );
			#endif
		}
	#endif
	#ifdef USE_ANISOTROPY
		vec3 getIBLAnisotropyRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
			#ifdef ENVMAP_TYPE_PMREM
				vec3 bentNormal = cross( bitangent, viewDir );
				bentNormal = normalize( cross( bentNormal, bitangent ) );
				bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
				return getIBLRadiance( viewDir, bentNormal, roughness );
			#else
				return vec3( 0.0 );
			#endif
		}
		#ifdef USE_RETROREFLECTION
			vec3 getIBLAnisotropyRetroRadiance( const in vec3 viewDir, const in vec3 normal, const in float roughness, const in vec3 bitangent, const in float anisotropy ) {
				#ifdef ENVMAP_TYPE_PMREM
					vec3 bentNormal = cross( bitangent, viewDir );
					bentNormal = normalize( cross( bentNormal, bitangent ) );
					bentNormal = normalize( mix( bentNormal, normal, pow2( pow2( 1.0 - anisotropy * ( 1.0 - roughness ) ) ) ) );
					return getIBLRetroRadiance( viewDir, bentNormal, roughness );
				#else
					return vec3( 0.0 );
				#endif
			}
		#endif
	#endif
#endif`,qS=`ToonMaterial material;
material.diffuseColor = diffuseColor.rgb;`,YS=`varying vec3 vViewPosition;
struct ToonMaterial {
	vec3 diffuseColor;
};
void RE_Direct_Toon( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 irradiance = getGradientIrradiance( geometryNormal, directLight.direction ) * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
void RE_IndirectDiffuse_Toon( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in ToonMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_Toon
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Toon`,$S=`BlinnPhongMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.specularColor = specular;
material.specularShininess = shininess;
material.specularStrength = specularStrength;`,ZS=`varying vec3 vViewPosition;
struct BlinnPhongMaterial {
	vec3 diffuseColor;
	vec3 specularColor;
	float specularShininess;
	float specularStrength;
};
void RE_Direct_BlinnPhong( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	reflectedLight.directDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
	reflectedLight.directSpecular += irradiance * BRDF_BlinnPhong( directLight.direction, geometryViewDir, geometryNormal, material.specularColor, material.specularShininess ) * material.specularStrength;
}
void RE_IndirectDiffuse_BlinnPhong( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in BlinnPhongMaterial material, inout ReflectedLight reflectedLight ) {
	reflectedLight.indirectDiffuse += irradiance * BRDF_Lambert( material.diffuseColor );
}
#define RE_Direct				RE_Direct_BlinnPhong
#define RE_IndirectDiffuse		RE_IndirectDiffuse_BlinnPhong`,KS=`PhysicalMaterial material;
material.diffuseColor = diffuseColor.rgb;
material.diffuseContribution = diffuseColor.rgb * ( 1.0 - metalnessFactor );
material.metalness = metalnessFactor;
vec3 dxy = max( abs( dFdx( nonPerturbedNormal ) ), abs( dFdy( nonPerturbedNormal ) ) );
float geometryRoughness = max( max( dxy.x, dxy.y ), dxy.z );
material.roughness = max( roughnessFactor, 0.045 );
material.roughness += geometryRoughness;
material.roughness = min( material.roughness, 1.0 );
#ifdef USE_DIFFUSE_ROUGHNESS
	float diffuseRoughnessFactor = diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		diffuseRoughnessFactor *= texture2D( diffuseRoughnessMap, vDiffuseRoughnessMapUv ).r;
	#endif
	material.diffuseRoughness = saturate( diffuseRoughnessFactor );
#endif
#ifdef IOR
	material.ior = ior;
	#ifdef USE_SPECULAR
		float specularIntensityFactor = specularIntensity;
		vec3 specularColorFactor = specularColor;
		#ifdef USE_SPECULAR_COLORMAP
			specularColorFactor *= texture2D( specularColorMap, vSpecularColorMapUv ).rgb;
		#endif
		#ifdef USE_SPECULAR_INTENSITYMAP
			specularIntensityFactor *= texture2D( specularIntensityMap, vSpecularIntensityMapUv ).a;
		#endif
		material.specularF90 = mix( specularIntensityFactor, 1.0, metalnessFactor );
	#else
		float specularIntensityFactor = 1.0;
		vec3 specularColorFactor = vec3( 1.0 );
		material.specularF90 = 1.0;
	#endif
	material.specularColor = min( pow2( ( material.ior - 1.0 ) / ( material.ior + 1.0 ) ) * specularColorFactor, vec3( 1.0 ) ) * specularIntensityFactor;
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
#else
	material.specularColor = vec3( 0.04 );
	material.specularColorBlended = mix( material.specularColor, diffuseColor.rgb, metalnessFactor );
	material.specularF90 = 1.0;
#endif
#ifdef USE_CLEARCOAT
	material.clearcoat = clearcoat;
	material.clearcoatRoughness = clearcoatRoughness;
	material.clearcoatF0 = vec3( 0.04 );
	material.clearcoatF90 = 1.0;
	#ifdef USE_CLEARCOATMAP
		material.clearcoat *= texture2D( clearcoatMap, vClearcoatMapUv ).x;
	#endif
	#ifdef USE_CLEARCOAT_ROUGHNESSMAP
		material.clearcoatRoughness *= texture2D( clearcoatRoughnessMap, vClearcoatRoughnessMapUv ).y;
	#endif
	material.clearcoat = saturate( material.clearcoat );	material.clearcoatRoughness = max( material.clearcoatRoughness, 0.045 );
	material.clearcoatRoughness += geometryRoughness;
	material.clearcoatRoughness = min( material.clearcoatRoughness, 1.0 );
#endif
#ifdef USE_DISPERSION
	material.dispersion = dispersion;
#endif
#ifdef USE_RETROREFLECTION
	material.retroreflectivity = retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	material.iridescence = iridescence;
	material.iridescenceIOR = iridescenceIOR;
	#ifdef USE_IRIDESCENCEMAP
		material.iridescence *= texture2D( iridescenceMap, vIridescenceMapUv ).r;
	#endif
	#ifdef USE_IRIDESCENCE_THICKNESSMAP
		material.iridescenceThickness = (iridescenceThicknessMaximum - iridescenceThicknessMinimum) * texture2D( iridescenceThicknessMap, vIridescenceThicknessMapUv ).g + iridescenceThicknessMinimum;
	#else
		material.iridescenceThickness = iridescenceThicknessMaximum;
	#endif
#endif
#ifdef USE_SHEEN
	material.sheenColor = sheenColor;
	#ifdef USE_SHEEN_COLORMAP
		material.sheenColor *= texture2D( sheenColorMap, vSheenColorMapUv ).rgb;
	#endif
	material.sheenRoughness = clamp( sheenRoughness, 0.0001, 1.0 );
	#ifdef USE_SHEEN_ROUGHNESSMAP
		material.sheenRoughness *= texture2D( sheenRoughnessMap, vSheenRoughnessMapUv ).a;
	#endif
#endif
#ifdef USE_ANISOTROPY
	#ifdef USE_ANISOTROPYMAP
		mat2 anisotropyMat = mat2( anisotropyVector.x, anisotropyVector.y, - anisotropyVector.y, anisotropyVector.x );
		vec3 anisotropyPolar = texture2D( anisotropyMap, vAnisotropyMapUv ).rgb;
		vec2 anisotropyV = anisotropyMat * normalize( 2.0 * anisotropyPolar.rg - vec2( 1.0 ) ) * anisotropyPolar.b;
	#else
		vec2 anisotropyV = anisotropyVector;
	#endif
	material.anisotropy = length( anisotropyV );
	if( material.anisotropy == 0.0 ) {
		anisotropyV = vec2( 1.0, 0.0 );
	} else {
		anisotropyV /= material.anisotropy;
		material.anisotropy = saturate( material.anisotropy );
	}
	material.alphaT = mix( pow2( material.roughness ), 1.0, pow2( material.anisotropy ) );
	material.anisotropyT = tbn[ 0 ] * anisotropyV.x + tbn[ 1 ] * anisotropyV.y;
	material.anisotropyB = tbn[ 1 ] * anisotropyV.x - tbn[ 0 ] * anisotropyV.y;
#endif`,JS=`uniform sampler2D dfgLUT;
struct PhysicalMaterial {
	vec3 diffuseColor;
	vec3 diffuseContribution;
	vec3 specularColor;
	vec3 specularColorBlended;
	float roughness;
	float metalness;
	float specularF90;
	float dispersion;
	vec2 dfg;
	vec3 multiScatteringCompensation;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float diffuseRoughness;
	#endif
	#ifdef USE_RETROREFLECTION
		float retroreflectivity;
	#endif
	#ifdef USE_CLEARCOAT
		float clearcoat;
		float clearcoatRoughness;
		vec3 clearcoatF0;
		float clearcoatF90;
	#endif
	#ifdef USE_IRIDESCENCE
		float iridescence;
		float iridescenceIOR;
		float iridescenceThickness;
		vec3 iridescenceFresnel;
		vec3 iridescenceF0Dielectric;
		vec3 iridescenceF0Metallic;
	#endif
	#ifdef USE_SHEEN
		vec3 sheenColor;
		float sheenRoughness;
	#endif
	#ifdef IOR
		float ior;
	#endif
	#ifdef USE_TRANSMISSION
		float transmission;
		float transmissionAlpha;
		float thickness;
		float attenuationDistance;
		vec3 attenuationColor;
	#endif
	#ifdef USE_ANISOTROPY
		float anisotropy;
		float alphaT;
		vec3 anisotropyT;
		vec3 anisotropyB;
	#endif
};
vec3 clearcoatSpecularDirect = vec3( 0.0 );
vec3 clearcoatSpecularIndirect = vec3( 0.0 );
vec3 sheenSpecularDirect = vec3( 0.0 );
vec3 sheenSpecularIndirect = vec3(0.0 );
vec3 Schlick_to_F0( const in vec3 f, const in float f90, const in float dotVH ) {
    float x = clamp( 1.0 - dotVH, 0.0, 1.0 );
    float x2 = x * x;
    float x5 = clamp( x * x2 * x2, 0.0, 0.9999 );
    return ( f - vec3( f90 ) * x5 ) / ( 1.0 - x5 );
}
#ifdef USE_DIFFUSE_ROUGHNESS
	const float EON_EPSILON = 1e-7;
	float FON_DirectionalAlbedo( const in float mu, const in float roughness, const in float A ) {
		float muComp = 1.0 - mu;
		float gOverPi = muComp * ( 0.0571085289 + muComp * ( 0.491881867 + muComp * ( - 0.332181442 + muComp * 0.0714429953 ) ) );
		return A * ( 1.0 + roughness * gOverPi );
	}
	vec3 BRDF_EON( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in vec3 diffuseColor, const in float roughness ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return BRDF_Lambert( rho );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float s = dot( lightDir, viewDir ) - dotNL * dotNV;
		float sOverT = ( s > 0.0 ) ? s / max( max( dotNL, dotNV ), EON_EPSILON ) : s;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		vec3 singleScatter = rho * RECIPROCAL_PI * A * ( 1.0 + roughness * sOverT );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		float albedoV = FON_DirectionalAlbedo( dotNV, roughness, A );
		float albedoL = FON_DirectionalAlbedo( dotNL, roughness, A );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		vec3 multiScatter = rhoMultiScatter * RECIPROCAL_PI
			* max( EON_EPSILON, 1.0 - albedoV )
			* max( EON_EPSILON, 1.0 - albedoL )
			/ max( EON_EPSILON, 1.0 - averageAlbedo );
		return singleScatter + multiScatter;
	}
	vec3 EON_DirectionalAlbedo( const in vec3 diffuseColor, const in float roughness, const in float dotNV ) {
		vec3 rho = saturate( diffuseColor );
		if ( roughness <= EON_EPSILON ) return rho;
		float A = 1.0 / ( 1.0 + ( 0.5 - 2.0 / ( 3.0 * PI ) ) * roughness );
		float directionalAlbedo = FON_DirectionalAlbedo( dotNV, roughness, A );
		float averageAlbedo = A * ( 1.0 + ( 2.0 / 3.0 - 28.0 / ( 15.0 * PI ) ) * roughness );
		vec3 rhoMultiScatter = rho * rho * averageAlbedo / max( vec3( EON_EPSILON ), vec3( 1.0 ) - rho * ( 1.0 - averageAlbedo ) );
		return rho * directionalAlbedo + rhoMultiScatter * ( 1.0 - directionalAlbedo );
	}
#endif
float V_GGX_SmithCorrelated( const in float alpha, const in float dotNL, const in float dotNV ) {
	float a2 = pow2( alpha );
	float gv = dotNL * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNV ) );
	float gl = dotNV * sqrt( a2 + ( 1.0 - a2 ) * pow2( dotNL ) );
	return 0.5 / max( gv + gl, EPSILON );
}
float D_GGX( const in float alpha, const in float dotNH ) {
	float a2 = pow2( alpha );
	float denom = pow2( dotNH ) * ( a2 - 1.0 ) + 1.0;
	return RECIPROCAL_PI * a2 / pow2( denom );
}
#ifdef USE_ANISOTROPY
	float V_GGX_SmithCorrelated_Anisotropic( const in float alphaT, const in float alphaB, const in float dotTV, const in float dotBV, const in float dotTL, const in float dotBL, const in float dotNV, const in float dotNL ) {
		float gv = dotNL * length( vec3( alphaT * dotTV, alphaB * dotBV, dotNV ) );
		float gl = dotNV * length( vec3( alphaT * dotTL, alphaB * dotBL, dotNL ) );
		return 0.5 / max( gv + gl, EPSILON );
	}
	float D_GGX_Anisotropic( const in float alphaT, const in float alphaB, const in float dotNH, const in float dotTH, const in float dotBH ) {
		float a2 = alphaT * alphaB;
		highp vec3 v = vec3( alphaB * dotTH, alphaT * dotBH, a2 * dotNH );
		highp float v2 = dot( v, v );
		float w2 = a2 / v2;
		return RECIPROCAL_PI * a2 * pow2 ( w2 );
	}
#endif
#ifdef USE_CLEARCOAT
	vec3 BRDF_GGX_Clearcoat( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material) {
		vec3 f0 = material.clearcoatF0;
		float f90 = material.clearcoatF90;
		float roughness = max( material.clearcoatRoughness, 0.045 );
		float alpha = pow2( roughness );
		vec3 halfDir = normalize( lightDir + viewDir );
		float dotNL = saturate( dot( normal, lightDir ) );
		float dotNV = saturate( dot( normal, viewDir ) );
		float dotNH = saturate( dot( normal, halfDir ) );
		float dotVH = saturate( dot( viewDir, halfDir ) );
		vec3 F = F_Schlick( f0, f90, dotVH );
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
		return F * ( V * D );
	}
#endif
vec3 BRDF_GGX( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, const in PhysicalMaterial material ) {
	vec3 f0 = material.specularColorBlended;
	float f90 = material.specularF90;
	float roughness = max( material.roughness, 0.045 );
	float alpha = pow2( roughness );
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float dotVH = saturate( dot( viewDir, halfDir ) );
	vec3 F = F_Schlick( f0, f90, dotVH );
	#ifdef USE_IRIDESCENCE
		F = mix( F, material.iridescenceFresnel, material.iridescence );
	#endif
	#ifdef USE_ANISOTROPY
		float dotTL = dot( material.anisotropyT, lightDir );
		float dotTV = dot( material.anisotropyT, viewDir );
		float dotTH = dot( material.anisotropyT, halfDir );
		float dotBL = dot( material.anisotropyB, lightDir );
		float dotBV = dot( material.anisotropyB, viewDir );
		float dotBH = dot( material.anisotropyB, halfDir );
		float alphaT = max( material.alphaT, alpha );
		float V = V_GGX_SmithCorrelated_Anisotropic( alphaT, alpha, dotTV, dotBV, dotTL, dotBL, dotNV, dotNL );
		float D = D_GGX_Anisotropic( alphaT, alpha, dotNH, dotTH, dotBH );
	#else
		float V = V_GGX_SmithCorrelated( alpha, dotNL, dotNV );
		float D = D_GGX( alpha, dotNH );
	#endif
	return F * ( V * D );
}
vec2 LTC_Uv( const in vec3 N, const in vec3 V, const in float roughness ) {
	const float LUT_SIZE = 64.0;
	const float LUT_SCALE = ( LUT_SIZE - 1.0 ) / LUT_SIZE;
	const float LUT_BIAS = 0.5 / LUT_SIZE;
	float dotNV = saturate( dot( N, V ) );
	vec2 uv = vec2( roughness, sqrt( 1.0 - dotNV ) );
	uv = uv * LUT_SCALE + LUT_BIAS;
	return uv;
}
float LTC_ClippedSphereFormFactor( const in vec3 f ) {
	float l = length( f );
	return max( ( l * l + f.z ) / ( l + 1.0 ), 0.0 );
}
vec3 LTC_EdgeVectorFormFactor( const in vec3 v1, const in vec3 v2 ) {
	float x = dot( v1, v2 );
	float y = abs( x );
	float a = 0.8543985 + ( 0.4965155 + 0.0145206 * y ) * y;
	float b = 3.4175940 + ( 4.1616724 + y ) * y;
	float v = a / b;
	float theta_sintheta = ( x > 0.0 ) ? v : 0.5 * inversesqrt( max( 1.0 - x * x, 1e-7 ) ) - v;
	return cross( v1, v2 ) * theta_sintheta;
}
vec3 LTC_Evaluate( const in vec3 N, const in vec3 V, const in vec3 P, const in mat3 mInv, const in vec3 rectCoords[ 4 ] ) {
	vec3 v1 = rectCoords[ 1 ] - rectCoords[ 0 ];
	vec3 v2 = rectCoords[ 3 ] - rectCoords[ 0 ];
	vec3 lightNormal = cross( v1, v2 );
	if( dot( lightNormal, P - rectCoords[ 0 ] ) < 0.0 ) return vec3( 0.0 );
	vec3 T1, T2;
	T1 = normalize( V - N * dot( V, N ) );
	T2 = - cross( N, T1 );
	mat3 mat = mInv * transpose( mat3( T1, T2, N ) );
	vec3 coords[ 4 ];
	coords[ 0 ] = mat * ( rectCoords[ 0 ] - P );
	coords[ 1 ] = mat * ( rectCoords[ 1 ] - P );
	coords[ 2 ] = mat * ( rectCoords[ 2 ] - P );
	coords[ 3 ] = mat * ( rectCoords[ 3 ] - P );
	coords[ 0 ] = normalize( coords[ 0 ] );
	coords[ 1 ] = normalize( coords[ 1 ] );
	coords[ 2 ] = normalize( coords[ 2 ] );
	coords[ 3 ] = normalize( coords[ 3 ] );
	vec3 vectorFormFactor = vec3( 0.0 );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 0 ], coords[ 1 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 1 ], coords[ 2 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 2 ], coords[ 3 ] );
	vectorFormFactor += LTC_EdgeVectorFormFactor( coords[ 3 ], coords[ 0 ] );
	float result = LTC_ClippedSphereFormFactor( vectorFormFactor );
	return vec3( result );
}
#if defined( USE_SHEEN )
float D_Charlie( float roughness, float dotNH ) {
	float alpha = pow2( roughness );
	float invAlpha = 1.0 / alpha;
	float cos2h = dotNH * dotNH;
	float sin2h = max( 1.0 - cos2h, 0.0078125 );
	return ( 2.0 + invAlpha ) * pow( sin2h, invAlpha * 0.5 ) / ( 2.0 * PI );
}
float V_Neubelt( float dotNV, float dotNL ) {
	return saturate( 1.0 / ( 4.0 * ( dotNL + dotNV - dotNL * dotNV ) ) );
}
vec3 BRDF_Sheen( const in vec3 lightDir, const in vec3 viewDir, const in vec3 normal, vec3 sheenColor, const in float sheenRoughness ) {
	vec3 halfDir = normalize( lightDir + viewDir );
	float dotNL = saturate( dot( normal, lightDir ) );
	float dotNV = saturate( dot( normal, viewDir ) );
	float dotNH = saturate( dot( normal, halfDir ) );
	float D = D_Charlie( sheenRoughness, dotNH );
	float V = V_Neubelt( dotNV, dotNL );
	return sheenColor * ( D * V );
}
#endif
float IBLSheenBRDF( const in vec3 normal, const in vec3 viewDir, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	float r2 = roughness * roughness;
	float rInv = 1.0 / ( roughness + 0.1 );
	float a = -1.9362 + 1.0678 * roughness + 0.4573 * r2 - 0.8469 * rInv;
	float b = -0.6014 + 0.5538 * roughness - 0.4670 * r2 - 0.1255 * rInv;
	float DG = exp( a * dotNV + b );
	return saturate( DG );
}
vec3 EnvironmentBRDF( const in vec3 normal, const in vec3 viewDir, const in vec3 specularColor, const in float specularF90, const in float roughness ) {
	float dotNV = saturate( dot( normal, viewDir ) );
	vec2 fab = texture2D( dfgLUT, vec2( roughness, dotNV ) ).rg;
	return specularColor * fab.x + specularF90 * fab.y;
}
#ifdef USE_IRIDESCENCE
void computeMultiscatteringIridescence( const in vec2 fab, const in vec3 specularColor, const in float specularF90, const in float iridescence, const in vec3 iridescenceF0, inout vec3 singleScatter, inout vec3 multiScatter ) {
#else
void computeMultiscattering( const in vec2 fab, const in vec3 specularColor, const in float specularF90, inout vec3 singleScatter, inout vec3 multiScatter ) {
#endif
	#ifdef USE_IRIDESCENCE
		vec3 Fr = mix( specularColor, iridescenceF0, iridescence );
	#else
		vec3 Fr = specularColor;
	#endif
	vec3 FssEss = Fr * fab.x + specularF90 * fab.y;
	float Ess = fab.x + fab.y;
	float Ems = 1.0 - Ess;
	vec3 Favg = Fr + ( 1.0 - Fr ) * 0.047619;	vec3 Fms = FssEss * Favg / ( 1.0 - Ems * Favg );
	singleScatter += FssEss;
	multiScatter += Fms * Ems;
}
#if NUM_RECT_AREA_LIGHTS > 0
	void RE_Direct_RectArea_Physical( const in RectAreaLight rectAreaLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
		vec3 normal = geometryNormal;
		vec3 viewDir = geometryViewDir;
		vec3 position = geometryPosition;
		vec3 lightPos = rectAreaLight.position;
		vec3 halfWidth = rectAreaLight.halfWidth;
		vec3 halfHeight = rectAreaLight.halfHeight;
		vec3 lightColor = rectAreaLight.color;
		float roughness = material.roughness;
		vec3 rectCoords[ 4 ];
		rectCoords[ 0 ] = lightPos + halfWidth - halfHeight;		rectCoords[ 1 ] = lightPos - halfWidth - halfHeight;
		rectCoords[ 2 ] = lightPos - halfWidth + halfHeight;
		rectCoords[ 3 ] = lightPos + halfWidth + halfHeight;
		vec2 uv = LTC_Uv( normal, viewDir, roughness );
		vec4 t1 = texture2D( ltc_1, uv );
		vec4 t2 = texture2D( ltc_2, uv );
		mat3 mInv = mat3(
			vec3( t1.x, 0, t1.y ),
			vec3(    0, 1,    0 ),
			vec3( t1.z, 0, t1.w )
		);
		vec3 fresnel = ( material.specularColorBlended * t2.x + ( material.specularF90 - material.specularColorBlended ) * t2.y );
		reflectedLight.directSpecular += lightColor * fresnel * LTC_Evaluate( normal, viewDir, position, mInv, rectCoords );
		reflectedLight.directDiffuse += lightColor * material.diffuseContribution * LTC_Evaluate( normal, viewDir, position, mat3( 1.0 ), rectCoords );
		#ifdef USE_CLEARCOAT
			vec3 Ncc = geometryClearcoatNormal;
			vec2 uvClearcoat = LTC_Uv( Ncc, viewDir, material.clearcoatRoughness );
			vec4 t1Clearcoat = texture2D( ltc_1, uvClearcoat );
			vec4 t2Clearcoat = texture2D( ltc_2, uvClearcoat );
			mat3 mInvClearcoat = mat3(
				vec3( t1Clearcoat.x, 0, t1Clearcoat.y ),
				vec3(             0, 1,             0 ),
				vec3( t1Clearcoat.z, 0, t1Clearcoat.w )
			);
			vec3 fresnelClearcoat = material.clearcoatF0 * t2Clearcoat.x + ( material.clearcoatF90 - material.clearcoatF0 ) * t2Clearcoat.y;
			clearcoatSpecularDirect += lightColor * fresnelClearcoat * LTC_Evaluate( Ncc, viewDir, position, mInvClearcoat, rectCoords );
		#endif
	}
#endif
void RE_Direct_Physical( const in IncidentLight directLight, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	float dotNL = saturate( dot( geometryNormal, directLight.direction ) );
	vec3 irradiance = dotNL * directLight.color;
	#ifdef USE_CLEARCOAT
		float dotNLcc = saturate( dot( geometryClearcoatNormal, directLight.direction ) );
		vec3 ccIrradiance = dotNLcc * directLight.color;
		clearcoatSpecularDirect += ccIrradiance * BRDF_GGX_Clearcoat( directLight.direction, geometryViewDir, geometryClearcoatNormal, material );
	#endif
	#ifdef USE_SHEEN
 
 		sheenSpecularDirect += irradiance * BRDF_Sheen( directLight.direction, geometryViewDir, geometryNormal, material.sheenColor, material.sheenRoughness );
 
 		float sheenAlbedoV = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
 		float sheenAlbedoL = IBLSheenBRDF( geometryNormal, directLight.direction, material.sheenRoughness );
 
 		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * max( sheenAlbedoV, sheenAlbedoL );
 
 		irradiance *= sheenEnergyComp;
 
 	#endif
	vec3 specularBRDF = BRDF_GGX( directLight.direction, geometryViewDir, geometryNormal, material );
	#ifdef USE_RETROREFLECTION
		vec3 retroViewDir = reflect( - geometryViewDir, geometryNormal );
		vec3 retroSpecularBRDF = BRDF_GGX( directLight.direction, retroViewDir, geometryNormal, material );
		specularBRDF = mix( specularBRDF, retroSpecularBRDF, saturate( material.retroreflectivity ) );
	#endif
	reflectedLight.directSpecular += irradiance * specularBRDF * material.multiScatteringCompensation;
	vec3 halfDir = normalize( directLight.direction + geometryViewDir );
	float dotVH = saturate( dot( geometryViewDir, halfDir ) );
	vec3 F = F_Schlick( material.specularColor, material.specularF90, dotVH );
	#ifdef USE_RETROREFLECTION
		vec3 retroHalfDir = normalize( directLight.direction + retroViewDir );
		float dotRetroVH = saturate( dot( retroViewDir, retroHalfDir ) );
		vec3 retroF = F_Schlick( material.specularColor, material.specularF90, dotRetroVH );
		F = mix( F, retroF, saturate( material.retroreflectivity ) );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		vec3 diffuseBRDF = BRDF_EON( directLight.direction, geometryViewDir, geometryNormal, material.diffuseColor, material.diffuseRoughness ) * ( 1.0 - material.metalness );
	#else
		vec3 diffuseBRDF = BRDF_Lambert( material.diffuseContribution );
	#endif
	reflectedLight.directDiffuse += irradiance * diffuseBRDF * ( 1.0 - F );
}
void RE_IndirectDiffuse_Physical( const in vec3 irradiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight ) {
	vec3 singleScattering = vec3( 0.0 );
	vec3 multiScattering = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScattering, multiScattering );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScattering, multiScattering );
	#endif
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuseAlbedo = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness );
		vec3 diffuse = irradiance * RECIPROCAL_PI * diffuseAlbedo * ( 1.0 - singleScattering - multiScattering );
	#else
		vec3 diffuse = irradiance * BRDF_Lambert( material.diffuseContribution ) * ( 1.0 - singleScattering - multiScattering );
	#endif
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		sheenSpecularIndirect += irradiance * material.sheenColor * sheenAlbedo * RECIPROCAL_PI;
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		diffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectDiffuse += diffuse;
}
void RE_IndirectSpecular_Physical( const in vec3 radiance, const in vec3 irradiance, const in vec3 clearcoatRadiance, const in vec3 geometryPosition, const in vec3 geometryNormal, const in vec3 geometryViewDir, const in vec3 geometryClearcoatNormal, const in PhysicalMaterial material, inout ReflectedLight reflectedLight) {
	#ifdef USE_CLEARCOAT
		clearcoatSpecularIndirect += clearcoatRadiance * EnvironmentBRDF( geometryClearcoatNormal, geometryViewDir, material.clearcoatF0, material.clearcoatF90, material.clearcoatRoughness );
	#endif
	#ifdef USE_SHEEN
		sheenSpecularIndirect += irradiance * material.sheenColor * IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness ) * RECIPROCAL_PI;
 	#endif
	vec3 singleScatteringDielectric = vec3( 0.0 );
	vec3 multiScatteringDielectric = vec3( 0.0 );
	vec3 singleScatteringMetallic = vec3( 0.0 );
	vec3 multiScatteringMetallic = vec3( 0.0 );
	#ifdef USE_IRIDESCENCE
		computeMultiscatteringIridescence( material.dfg, material.specularColor, material.specularF90, material.iridescence, material.iridescenceF0Dielectric, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscatteringIridescence( material.dfg, material.diffuseColor, material.specularF90, material.iridescence, material.iridescenceF0Metallic, singleScatteringMetallic, multiScatteringMetallic );
	#else
		computeMultiscattering( material.dfg, material.specularColor, material.specularF90, singleScatteringDielectric, multiScatteringDielectric );
		computeMultiscattering( material.dfg, material.diffuseColor, material.specularF90, singleScatteringMetallic, multiScatteringMetallic );
	#endif
	vec3 singleScattering = mix( singleScatteringDielectric, singleScatteringMetallic, material.metalness );
	vec3 multiScattering = mix( multiScatteringDielectric, multiScatteringMetallic, material.metalness );
	vec3 totalScatteringDielectric = singleScatteringDielectric + multiScatteringDielectric;
	#ifdef USE_DIFFUSE_ROUGHNESS
		float dotNV = saturate( dot( geometryNormal, geometryViewDir ) );
		vec3 diffuse = EON_DirectionalAlbedo( material.diffuseColor, material.diffuseRoughness, dotNV ) * ( 1.0 - material.metalness ) * ( 1.0 - totalScatteringDielectric );
	#else
		vec3 diffuse = material.diffuseContribution * ( 1.0 - totalScatteringDielectric );
	#endif
	vec3 cosineWeightedIrradiance = irradiance * RECIPROCAL_PI;
	vec3 indirectSpecular = radiance * singleScattering;
	indirectSpecular += multiScattering * cosineWeightedIrradiance;
	vec3 indirectDiffuse = diffuse * cosineWeightedIrradiance;
	#ifdef USE_SHEEN
		float sheenAlbedo = IBLSheenBRDF( geometryNormal, geometryViewDir, material.sheenRoughness );
		float sheenEnergyComp = 1.0 - max3( material.sheenColor ) * sheenAlbedo;
		indirectSpecular *= sheenEnergyComp;
		indirectDiffuse *= sheenEnergyComp;
	#endif
	reflectedLight.indirectSpecular += indirectSpecular;
	reflectedLight.indirectDiffuse += indirectDiffuse;
}
#define RE_Direct				RE_Direct_Physical
#define RE_Direct_RectArea		RE_Direct_RectArea_Physical
#define RE_IndirectDiffuse		RE_IndirectDiffuse_Physical
#define RE_IndirectSpecular		RE_IndirectSpecular_Physical
float computeSpecularOcclusion( const in float dotNV, const in float ambientOcclusion, const in float roughness ) {
	return saturate( pow( dotNV + ambientOcclusion, exp2( - 16.0 * roughness - 1.0 ) ) - 1.0 + ambientOcclusion );
}`,jS=`
vec3 geometryPosition = - vViewPosition;
vec3 geometryNormal = normal;
vec3 geometryViewDir = ( isOrthographic ) ? vec3( 0, 0, 1 ) : normalize( vViewPosition );
vec3 geometryClearcoatNormal = vec3( 0.0 );
#ifdef USE_CLEARCOAT
	geometryClearcoatNormal = clearcoatNormal;
#endif
#ifdef USE_IRIDESCENCE
	float dotNVi = saturate( dot( normal, geometryViewDir ) );
	if ( material.iridescenceThickness == 0.0 ) {
		material.iridescence = 0.0;
	} else {
		material.iridescence = saturate( material.iridescence );
	}
	if ( material.iridescence > 0.0 ) {
		vec3 iridescenceFresnelDielectric = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.specularColor );
		vec3 iridescenceFresnelMetallic = evalIridescence( 1.0, material.iridescenceIOR, dotNVi, material.iridescenceThickness, material.diffuseColor );
		material.iridescenceFresnel = mix( iridescenceFresnelDielectric, iridescenceFresnelMetallic, material.metalness );
		material.iridescenceF0Dielectric = Schlick_to_F0( iridescenceFresnelDielectric, 1.0, dotNVi );
		material.iridescenceF0Metallic = Schlick_to_F0( iridescenceFresnelMetallic, 1.0, dotNVi );
	}
#endif
#ifdef STANDARD
	float dotNVms = saturate( dot( geometryNormal, geometryViewDir ) );
	material.dfg = texture2D( dfgLUT, vec2( material.roughness, dotNVms ) ).rg;
	#if ( NUM_SUN_LIGHTS > 0 || NUM_DIR_LIGHTS > 0 || NUM_POINT_LIGHTS > 0 || NUM_SPOT_LIGHTS > 0 )
		float EssMs = material.dfg.x + material.dfg.y;
		material.multiScatteringCompensation = 1.0 + material.specularColorBlended * ( 1.0 / EssMs - 1.0 );
	#endif
#endif
IncidentLight directLight;
#if ( NUM_POINT_LIGHTS > 0 ) && defined( RE_Direct )
	PointLight pointLight;
	#if defined( USE_SHADOWMAP ) && NUM_POINT_LIGHT_SHADOWS > 0
	PointLightShadow pointLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHTS; i ++ ) {
		pointLight = pointLights[ i ];
		getPointLightInfo( pointLight, geometryPosition, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_POINT_LIGHT_SHADOWS ) && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
		pointLightShadow = pointLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getPointShadow( pointShadowMap[ i ], pointLightShadow.shadowMapSize, pointLightShadow.shadowIntensity, pointLightShadow.shadowBias, pointLightShadow.shadowRadius, vPointShadowCoord[ i ], pointLightShadow.shadowCameraNear, pointLightShadow.shadowCameraFar ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SPOT_LIGHTS > 0 ) && defined( RE_Direct )
	SpotLight spotLight;
	vec4 spotColor;
	vec3 spotLightCoord;
	bool inSpotLightMap;
	#if defined( USE_SHADOWMAP ) && NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHTS; i ++ ) {
		spotLight = spotLights[ i ];
		getSpotLightInfo( spotLight, geometryPosition, directLight );
		#if ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#define SPOT_LIGHT_MAP_INDEX UNROLLED_LOOP_INDEX
		#elif ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		#define SPOT_LIGHT_MAP_INDEX NUM_SPOT_LIGHT_MAPS
		#else
		#define SPOT_LIGHT_MAP_INDEX ( UNROLLED_LOOP_INDEX - NUM_SPOT_LIGHT_SHADOWS + NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS )
		#endif
		#if ( SPOT_LIGHT_MAP_INDEX < NUM_SPOT_LIGHT_MAPS )
			spotLightCoord = vSpotLightCoord[ i ].xyz / vSpotLightCoord[ i ].w;
			inSpotLightMap = all( lessThan( abs( spotLightCoord * 2. - 1. ), vec3( 1.0 ) ) );
			spotColor = texture2D( spotLightMap[ SPOT_LIGHT_MAP_INDEX ], spotLightCoord.xy );
			directLight.color = inSpotLightMap ? directLight.color * spotColor.rgb : directLight.color;
		#endif
		#undef SPOT_LIGHT_MAP_INDEX
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
		spotLightShadow = spotLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( spotShadowMap[ i ], spotLightShadow.shadowMapSize, spotLightShadow.shadowIntensity, spotLightShadow.shadowBias, spotLightShadow.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_SUN_LIGHTS > 0 ) && defined( RE_Direct )
	SunLight sunLight;
	#if defined( USE_SHADOWMAP ) && NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHTS; i ++ ) {
		sunLight = sunLights[ i ];
		getSunLightInfo( sunLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_SUN_LIGHT_SHADOWS )
		sunLightShadow = sunLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getSunShadow( sunShadowMap[ i ], sunLightShadow, UNROLLED_LOOP_INDEX ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_DIR_LIGHTS > 0 ) && defined( RE_Direct )
	DirectionalLight directionalLight;
	#if defined( USE_SHADOWMAP ) && NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLightShadow;
	#endif
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHTS; i ++ ) {
		directionalLight = directionalLights[ i ];
		getDirectionalLightInfo( directionalLight, directLight );
		#if defined( USE_SHADOWMAP ) && ( UNROLLED_LOOP_INDEX < NUM_DIR_LIGHT_SHADOWS )
		directionalLightShadow = directionalLightShadows[ i ];
		directLight.color *= ( directLight.visible && receiveShadow ) ? getShadow( directionalShadowMap[ i ], directionalLightShadow.shadowMapSize, directionalLightShadow.shadowIntensity, directionalLightShadow.shadowBias, directionalLightShadow.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
		#endif
		RE_Direct( directLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if ( NUM_RECT_AREA_LIGHTS > 0 ) && defined( RE_Direct_RectArea )
	RectAreaLight rectAreaLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_RECT_AREA_LIGHTS; i ++ ) {
		rectAreaLight = rectAreaLights[ i ];
		RE_Direct_RectArea( rectAreaLight, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
	}
	#pragma unroll_loop_end
#endif
#if defined( RE_IndirectDiffuse )
	vec3 iblIrradiance = vec3( 0.0 );
	vec3 irradiance = getAmbientLightIrradiance( ambientLightColor );
	#if defined( USE_LIGHT_PROBES )
		irradiance += getLightProbeIrradiance( lightProbe, geometryNormal );
	#endif
	#if ( NUM_HEMI_LIGHTS > 0 )
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_HEMI_LIGHTS; i ++ ) {
			irradiance += getHemisphereLightIrradiance( hemisphereLights[ i ], geometryNormal );
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_LIGHT_PROBE_GRIDS > 0
		vec3 probeWorldPos = ( ( vec4( geometryPosition, 1.0 ) - viewMatrix[ 3 ] ) * viewMatrix ).xyz;
		vec3 probeWorldNormal = transformNormalByInverseViewMatrix( geometryNormal, viewMatrix );
		int probeGrid = - 1;
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( isInsideLightProbeGrid( probeWorldPos, probeWorldNormal, probesMin[ i ], probesMax[ i ], probesResolution[ i ] ) ) probeGrid = UNROLLED_LOOP_INDEX;
		}
		#pragma unroll_loop_end
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_LIGHT_PROBE_GRIDS; i ++ ) {
			if ( probeGrid == UNROLLED_LOOP_INDEX ) irradiance += getLightProbeGridIrradiance( probesSH[ i ], probesMin[ i ], probesMax[ i ], probesResolution[ i ], probeWorldPos, probeWorldNormal );
		}
		#pragma unroll_loop_end
	#endif
#endif
#if defined( RE_IndirectSpecular )
	vec3 radiance = vec3( 0.0 );
	vec3 clearcoatRadiance = vec3( 0.0 );
#endif`,QS=`#if defined( RE_IndirectDiffuse )
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		vec3 lightMapIrradiance = lightMapTexel.rgb * lightMapIntensity;
		irradiance += lightMapIrradiance;
	#endif
	#if defined( USE_ENVMAP ) && defined( ENVMAP_TYPE_PMREM )
		#if defined( STANDARD ) || defined( LAMBERT ) || defined( PHONG )
			iblIrradiance += getIBLIrradiance( geometryNormal );
		#endif
	#endif
#endif
#if defined( USE_ENVMAP ) && defined( RE_IndirectSpecular )
	#ifdef USE_ANISOTROPY
		vec3 iblRadiance = getIBLAnisotropyRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
	#else
		vec3 iblRadiance = getIBLRadiance( geometryViewDir, geometryNormal, material.roughness );
	#endif
	#ifdef USE_RETROREFLECTION
		#ifdef USE_ANISOTROPY
			vec3 retroIBLRadiance = getIBLAnisotropyRetroRadiance( geometryViewDir, geometryNormal, material.roughness, material.anisotropyB, material.anisotropy );
		#else
			vec3 retroIBLRadiance = getIBLRetroRadiance( geometryViewDir, geometryNormal, material.roughness );
		#endif
		iblRadiance = mix( iblRadiance, retroIBLRadiance, saturate( material.retroreflectivity ) );
	#endif
	radiance += iblRadiance;
	#ifdef USE_CLEARCOAT
		clearcoatRadiance += getIBLRadiance( geometryViewDir, geometryClearcoatNormal, material.clearcoatRoughness );
	#endif
#endif`,eb=`#if defined( RE_IndirectDiffuse )
	#if defined( LAMBERT ) || defined( PHONG )
		irradiance += iblIrradiance;
	#endif
	RE_IndirectDiffuse( irradiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif
#if defined( RE_IndirectSpecular )
	RE_IndirectSpecular( radiance, iblIrradiance, clearcoatRadiance, geometryPosition, geometryNormal, geometryViewDir, geometryClearcoatNormal, material, reflectedLight );
#endif`,tb=`#if NUM_LIGHT_PROBE_GRIDS > 0
uniform highp sampler3D probesSH[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMin[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesMax[ NUM_LIGHT_PROBE_GRIDS ];
uniform vec3 probesResolution[ NUM_LIGHT_PROBE_GRIDS ];
bool isInsideLightProbeGrid( vec3 worldPos, vec3 worldNormal, vec3 probesMin, vec3 probesMax, vec3 probesResolution ) {
	vec3 spacing = ( probesMax - probesMin ) / probesResolution;
	vec3 samplePos = worldPos + worldNormal * spacing * 0.5;
	vec3 margin = spacing * 0.01;
	return all( greaterThanEqual( samplePos, probesMin - margin ) ) && all( lessThanEqual( samplePos, probesMax + margin ) );
}
vec3 getLightProbeGridIrradiance( highp sampler3D probesSH, vec3 probesMin, vec3 probesMax, vec3 probesResolution, vec3 worldPos, vec3 worldNormal ) {
	vec3 res = probesResolution;
	vec3 gridRange = probesMax - probesMin;
	vec3 probeSpacing = gridRange / res;
	vec3 samplePos = worldPos + worldNormal * probeSpacing * 0.5;
	vec3 uvw = clamp( ( samplePos - probesMin ) / gridRange, 0.5 / res, 1.0 - 0.5 / res );
	float nz          = res.z;
	float paddedSlices = nz + 2.0;
	float atlasDepth  = 7.0 * paddedSlices;
	float uvZBase     = uvw.z * nz + 1.0;
	vec4 s0 = texture( probesSH, vec3( uvw.xy, ( uvZBase                       ) / atlasDepth ) );
	vec4 s1 = texture( probesSH, vec3( uvw.xy, ( uvZBase +       paddedSlices   ) / atlasDepth ) );
	vec4 s2 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 2.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s3 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 3.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s4 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 4.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s5 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 5.0 * paddedSlices   ) / atlasDepth ) );
	vec4 s6 = texture( probesSH, vec3( uvw.xy, ( uvZBase + 6.0 * paddedSlices   ) / atlasDepth ) );
	vec3 c0 = s0.xyz;
	vec3 c1 = vec3( s0.w, s1.xy );
	vec3 c2 = vec3( s1.zw, s2.x );
	vec3 c3 = s2.yzw;
	vec3 c4 = s3.xyz;
	vec3 c5 = vec3( s3.w, s4.xy );
	vec3 c6 = vec3( s4.zw, s5.x );
	vec3 c7 = s5.yzw;
	vec3 c8 = s6.xyz;
	float x = worldNormal.x, y = worldNormal.y, z = worldNormal.z;
	vec3 result = c0 * 0.886227;
	result += c1 * 2.0 * 0.511664 * y;
	result += c2 * 2.0 * 0.511664 * z;
	result += c3 * 2.0 * 0.511664 * x;
	result += c4 * 2.0 * 0.429043 * x * y;
	result += c5 * 2.0 * 0.429043 * y * z;
	result += c6 * ( 0.743125 * z * z - 0.247708 );
	result += c7 * 2.0 * 0.429043 * x * z;
	result += c8 * 0.429043 * ( x * x - y * y );
	return max( result, vec3( 0.0 ) );
}
#endif`,nb=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	gl_FragDepth = vIsPerspective == 0.0 ? gl_FragCoord.z : log2( vFragDepth ) * logDepthBufFC * 0.5;
#endif`,ib=`#if defined( USE_LOGARITHMIC_DEPTH_BUFFER )
	uniform float logDepthBufFC;
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,sb=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	varying float vFragDepth;
	varying float vIsPerspective;
#endif`,rb=`#ifdef USE_LOGARITHMIC_DEPTH_BUFFER
	vFragDepth = 1.0 + gl_Position.w;
	vIsPerspective = float( isPerspectiveMatrix( projectionMatrix ) );
#endif`,ob=`#ifdef USE_MAP
	vec4 sampledDiffuseColor = texture2D( map, vMapUv );
	#ifdef DECODE_VIDEO_TEXTURE
		sampledDiffuseColor = sRGBTransferEOTF( sampledDiffuseColor );
	#endif
	diffuseColor *= sampledDiffuseColor;
#endif`,ab=`#ifdef USE_MAP
	uniform sampler2D map;
#endif`,lb=`#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
	#if defined( USE_POINTS_UV )
		vec2 uv = vUv;
	#else
		vec2 uv = ( uvTransform * vec3( gl_PointCoord.x, 1.0 - gl_PointCoord.y, 1 ) ).xy;
	#endif
#endif
#ifdef USE_MAP
	diffuseColor *= texture2D( map, uv );
#endif
#ifdef USE_ALPHAMAP
	diffuseColor.a *= texture2D( alphaMap, uv ).g;
#endif`,cb=`#if defined( USE_POINTS_UV )
	varying vec2 vUv;
#else
	#if defined( USE_MAP ) || defined( USE_ALPHAMAP )
		uniform mat3 uvTransform;
	#endif
#endif
#ifdef USE_MAP
	uniform sampler2D map;
#endif
#ifdef USE_ALPHAMAP
	uniform sampler2D alphaMap;
#endif`,hb=`float metalnessFactor = metalness;
#ifdef USE_METALNESSMAP
	vec4 texelMetalness = texture2D( metalnessMap, vMetalnessMapUv );
	metalnessFactor *= texelMetalness.b;
#endif`,ub=`#ifdef USE_METALNESSMAP
	uniform sampler2D metalnessMap;
#endif`,fb=`#ifdef USE_INSTANCING_MORPH
	float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	float morphTargetBaseInfluence = texelFetch( morphTexture, ivec2( 0, gl_InstanceID ), 0 ).r;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		morphTargetInfluences[i] =  texelFetch( morphTexture, ivec2( i + 1, gl_InstanceID ), 0 ).r;
	}
#endif`,db=`#if defined( USE_MORPHCOLORS )
	#if defined( USE_COLOR_ALPHA )
		vColor *= morphTargetBaseInfluence;
	#elif defined( USE_COLOR )
		vColor.rgb *= morphTargetBaseInfluence;
	#endif
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		#if defined( USE_COLOR_ALPHA )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor += getMorph( gl_VertexID, i, 2 ) * morphTargetInfluences[ i ];
		#elif defined( USE_COLOR )
			if ( morphTargetInfluences[ i ] != 0.0 ) vColor.rgb += getMorph( gl_VertexID, i, 2 ).rgb * morphTargetInfluences[ i ];
		#endif
	}
#endif`,pb=`#ifdef USE_MORPHNORMALS
	objectNormal *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) objectNormal += getMorph( gl_VertexID, i, 1 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,mb=`#ifdef USE_MORPHTARGETS
	#ifndef USE_INSTANCING_MORPH
		uniform float morphTargetBaseInfluence;
		uniform float morphTargetInfluences[ MORPHTARGETS_COUNT ];
	#endif
	uniform sampler2DArray morphTargetsTexture;
	uniform ivec2 morphTargetsTextureSize;
	vec4 getMorph( const in int vertexIndex, const in int morphTargetIndex, const in int offset ) {
		int texelIndex = vertexIndex * MORPHTARGETS_TEXTURE_STRIDE + offset;
		int y = texelIndex / morphTargetsTextureSize.x;
		int x = texelIndex - y * morphTargetsTextureSize.x;
		ivec3 morphUV = ivec3( x, y, morphTargetIndex );
		return texelFetch( morphTargetsTexture, morphUV, 0 );
	}
#endif`,gb=`#ifdef USE_MORPHTARGETS
	transformed *= morphTargetBaseInfluence;
	for ( int i = 0; i < MORPHTARGETS_COUNT; i ++ ) {
		if ( morphTargetInfluences[ i ] != 0.0 ) transformed += getMorph( gl_VertexID, i, 0 ).xyz * morphTargetInfluences[ i ];
	}
#endif`,_b=`float faceDirection = gl_FrontFacing ? 1.0 : - 1.0;
#ifdef FLAT_SHADED
	vec3 fdx = dFdx( vViewPosition );
	vec3 fdy = dFdy( vViewPosition );
	vec3 normal = normalize( cross( fdx, fdy ) );
#else
	vec3 normal = normalize( vNormal );
	#ifdef DOUBLE_SIDED
		normal *= faceDirection;
	#endif
#endif
#if defined( USE_NORMALMAP_TANGENTSPACE ) || defined( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY )
	#ifdef USE_TANGENT
		mat3 tbn = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn = getTangentFrame( - vViewPosition, normal,
		#if defined( USE_NORMALMAP )
			vNormalMapUv
		#elif defined( USE_CLEARCOAT_NORMALMAP )
			vClearcoatNormalMapUv
		#else
			vUv
		#endif
		);
	#endif
	#ifdef DOUBLE_SIDED
		tbn[0] *= faceDirection;
		tbn[1] *= faceDirection;
	#endif
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	#ifdef USE_TANGENT
		mat3 tbn2 = mat3( normalize( vTangent ), normalize( vBitangent ), normal );
	#else
		mat3 tbn2 = getTangentFrame( - vViewPosition, normal, vClearcoatNormalMapUv );
	#endif
	#ifdef DOUBLE_SIDED
		tbn2[0] *= faceDirection;
		tbn2[1] *= faceDirection;
	#endif
#endif
vec3 nonPerturbedNormal = normal;`,xb=`#ifdef USE_NORMALMAP_OBJECTSPACE
	normal = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#ifdef FLIP_SIDED
		normal = - normal;
	#endif
	#ifdef DOUBLE_SIDED
		normal = normal * faceDirection;
	#endif
	normal = normalize( normalMatrix * normal );
#elif defined( USE_NORMALMAP_TANGENTSPACE )
	vec3 mapN = texture2D( normalMap, vNormalMapUv ).xyz * 2.0 - 1.0;
	#if defined( USE_PACKED_NORMALMAP )
		mapN = vec3( mapN.xy, sqrt( saturate( 1.0 - dot( mapN.xy, mapN.xy ) ) ) );
	#endif
	mapN.xy *= normalScale;
	normal = normalize( tbn * mapN );
#elif defined( USE_BUMPMAP )
	normal = perturbNormalArb( - vViewPosition, normal, dHdxy_fwd(), faceDirection );
#endif`,yb=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,vb=`#ifndef FLAT_SHADED
	varying vec3 vNormal;
	#ifdef USE_TANGENT
		varying vec3 vTangent;
		varying vec3 vBitangent;
	#endif
#endif`,Sb=`#ifndef FLAT_SHADED
	vNormal = normalize( transformedNormal );
	#ifdef USE_TANGENT
		vTangent = normalize( transformedTangent );
		vBitangent = normalize( cross( vNormal, vTangent ) * tangent.w );
		#ifdef FLIP_SIDED
			vBitangent = - vBitangent;
		#endif
	#endif
#endif`,bb=`#ifdef USE_NORMALMAP
	uniform sampler2D normalMap;
	uniform vec2 normalScale;
#endif
#ifdef USE_NORMALMAP_OBJECTSPACE
	uniform mat3 normalMatrix;
#endif
#if ! defined ( USE_TANGENT ) && ( defined ( USE_NORMALMAP_TANGENTSPACE ) || defined ( USE_CLEARCOAT_NORMALMAP ) || defined( USE_ANISOTROPY ) )
	mat3 getTangentFrame( vec3 eye_pos, vec3 surf_norm, vec2 uv ) {
		vec3 q0 = dFdx( eye_pos.xyz );
		vec3 q1 = dFdy( eye_pos.xyz );
		vec2 st0 = dFdx( uv.st );
		vec2 st1 = dFdy( uv.st );
		vec3 N = surf_norm;
		vec3 q1perp = cross( q1, N );
		vec3 q0perp = cross( N, q0 );
		vec3 T = q1perp * st0.x + q0perp * st1.x;
		vec3 B = q1perp * st0.y + q0perp * st1.y;
		float det = max( dot( T, T ), dot( B, B ) );
		float scale = ( det == 0.0 ) ? 0.0 : inversesqrt( det );
		return mat3( T * scale, B * scale, N );
	}
#endif`,Mb=`#ifdef USE_CLEARCOAT
	vec3 clearcoatNormal = nonPerturbedNormal;
#endif`,wb=`#ifdef USE_CLEARCOAT_NORMALMAP
	vec3 clearcoatMapN = texture2D( clearcoatNormalMap, vClearcoatNormalMapUv ).xyz * 2.0 - 1.0;
	clearcoatMapN.xy *= clearcoatNormalScale;
	clearcoatNormal = normalize( tbn2 * clearcoatMapN );
#endif`,Eb=`#ifdef USE_CLEARCOATMAP
	uniform sampler2D clearcoatMap;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform sampler2D clearcoatNormalMap;
	uniform vec2 clearcoatNormalScale;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform sampler2D clearcoatRoughnessMap;
#endif`,Tb=`#ifdef USE_IRIDESCENCEMAP
	uniform sampler2D iridescenceMap;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform sampler2D iridescenceThicknessMap;
#endif`,Ab=`#ifdef OPAQUE
diffuseColor.a = 1.0;
#endif
#ifdef USE_TRANSMISSION
diffuseColor.a *= material.transmissionAlpha;
#endif
gl_FragColor = vec4( outgoingLight, diffuseColor.a );`,Rb=`vec3 packNormalToRGB( const in vec3 normal ) {
	return normalize( normal ) * 0.5 + 0.5;
}
vec3 unpackRGBToNormal( const in vec3 rgb ) {
	return 2.0 * rgb.xyz - 1.0;
}
const float PackUpscale = 256. / 255.;const float UnpackDownscale = 255. / 256.;const float ShiftRight8 = 1. / 256.;
const float Inv255 = 1. / 255.;
const vec4 PackFactors = vec4( 1.0, 256.0, 256.0 * 256.0, 256.0 * 256.0 * 256.0 );
const vec2 UnpackFactors2 = vec2( UnpackDownscale, 1.0 / PackFactors.g );
const vec3 UnpackFactors3 = vec3( UnpackDownscale / PackFactors.rg, 1.0 / PackFactors.b );
const vec4 UnpackFactors4 = vec4( UnpackDownscale / PackFactors.rgb, 1.0 / PackFactors.a );
vec4 packDepthToRGBA( const in float v ) {
	if( v <= 0.0 )
		return vec4( 0., 0., 0., 0. );
	if( v >= 1.0 )
		return vec4( 1., 1., 1., 1. );
	float vuf;
	float af = modf( v * PackFactors.a, vuf );
	float bf = modf( vuf * ShiftRight8, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec4( vuf * Inv255, gf * PackUpscale, bf * PackUpscale, af );
}
vec3 packDepthToRGB( const in float v ) {
	if( v <= 0.0 )
		return vec3( 0., 0., 0. );
	if( v >= 1.0 )
		return vec3( 1., 1., 1. );
	float vuf;
	float bf = modf( v * PackFactors.b, vuf );
	float gf = modf( vuf * ShiftRight8, vuf );
	return vec3( vuf * Inv255, gf * PackUpscale, bf );
}
vec2 packDepthToRG( const in float v ) {
	if( v <= 0.0 )
		return vec2( 0., 0. );
	if( v >= 1.0 )
		return vec2( 1., 1. );
	float vuf;
	float gf = modf( v * 256., vuf );
	return vec2( vuf * Inv255, gf );
}
float unpackRGBAToDepth( const in vec4 v ) {
	return dot( v, UnpackFactors4 );
}
float unpackRGBToDepth( const in vec3 v ) {
	return dot( v, UnpackFactors3 );
}
float unpackRGToDepth( const in vec2 v ) {
	return v.r * UnpackFactors2.r + v.g * UnpackFactors2.g;
}
vec4 pack2HalfToRGBA( const in vec2 v ) {
	vec4 r = vec4( v.x, fract( v.x * 255.0 ), v.y, fract( v.y * 255.0 ) );
	return vec4( r.x - r.y / 255.0, r.y, r.z - r.w / 255.0, r.w );
}
vec2 unpackRGBATo2Half( const in vec4 v ) {
	return vec2( v.x + ( v.y / 255.0 ), v.z + ( v.w / 255.0 ) );
}
float viewZToOrthographicDepth( const in float viewZ, const in float near, const in float far ) {
	return ( viewZ + near ) / ( near - far );
}
float orthographicDepthToViewZ( const in float depth, const in float near, const in float far ) {
	#ifdef USE_REVERSED_DEPTH_BUFFER
	
		return depth * ( far - near ) - far;
	#else
		return depth * ( near - far ) - near;
	#endif
}
float viewZToPerspectiveDepth( const in float viewZ, const in float near, const in float far ) {
	return ( ( near + viewZ ) * far ) / ( ( far - near ) * viewZ );
}
float perspectiveDepthToViewZ( const in float depth, const in float near, const in float far ) {
	
	#ifdef USE_REVERSED_DEPTH_BUFFER
		return ( near * far ) / ( ( near - far ) * depth - near );
	#else
		return ( near * far ) / ( ( far - near ) * depth - far );
	#endif
}`,Cb=`#ifdef PREMULTIPLIED_ALPHA
	gl_FragColor.rgb *= gl_FragColor.a;
#endif`,Ib=`vec4 mvPosition = vec4( transformed, 1.0 );
#ifdef USE_BATCHING
	mvPosition = batchingMatrix * mvPosition;
#endif
#ifdef USE_INSTANCING
	mvPosition = instanceMatrix * mvPosition;
#endif
mvPosition = modelViewMatrix * mvPosition;
gl_Position = projectionMatrix * mvPosition;`,Pb=`#ifdef DITHERING
	gl_FragColor.rgb = dithering( gl_FragColor.rgb );
#endif`,Lb=`#ifdef DITHERING
	vec3 dithering( vec3 color ) {
		float grid_position = rand( gl_FragCoord.xy );
		vec3 dither_shift_RGB = vec3( 0.25 / 255.0, -0.25 / 255.0, 0.25 / 255.0 );
		dither_shift_RGB = mix( 2.0 * dither_shift_RGB, -2.0 * dither_shift_RGB, grid_position );
		return color + dither_shift_RGB;
	}
#endif`,Nb=`float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
	vec4 texelRoughness = texture2D( roughnessMap, vRoughnessMapUv );
	roughnessFactor *= texelRoughness.g;
#endif`,Db=`#ifdef USE_ROUGHNESSMAP
	uniform sampler2D roughnessMap;
#endif`,Ub=`#if NUM_SPOT_LIGHT_COORDS > 0
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#if NUM_SPOT_LIGHT_MAPS > 0
	uniform sampler2D spotLightMap[ NUM_SPOT_LIGHT_MAPS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		#define SUN_LIGHT_CASCADES 2
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#else
			uniform sampler2D sunShadowMap[ NUM_SUN_LIGHT_SHADOWS ];
		#endif
		uniform mat4 sunShadowMatrix[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		uniform vec4 sunShadowCascade[ NUM_SUN_LIGHT_SHADOWS * SUN_LIGHT_CASCADES ];
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
		struct SunLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SunLightShadow sunLightShadows[ NUM_SUN_LIGHT_SHADOWS ];
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#else
			uniform sampler2D directionalShadowMap[ NUM_DIR_LIGHT_SHADOWS ];
		#endif
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform sampler2DShadow spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#else
			uniform sampler2D spotShadowMap[ NUM_SPOT_LIGHT_SHADOWS ];
		#endif
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#if defined( SHADOWMAP_TYPE_PCF )
			uniform samplerCubeShadow pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#elif defined( SHADOWMAP_TYPE_BASIC )
			uniform samplerCube pointShadowMap[ NUM_POINT_LIGHT_SHADOWS ];
		#endif
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float interleavedGradientNoise( vec2 position ) {
			return fract( 52.9829189 * fract( dot( position, vec2( 0.06711056, 0.00583715 ) ) ) );
		}
		vec2 vogelDiskSample( int sampleIndex, int samplesCount, float phi ) {
			const float goldenAngle = 2.399963229728653;
			float r = sqrt( ( float( sampleIndex ) + 0.5 ) / float( samplesCount ) );
			float theta = float( sampleIndex ) * goldenAngle + phi;
			return vec2( cos( theta ), sin( theta ) ) * r;
		}
	#endif
	#if defined( SHADOWMAP_TYPE_PCF )
		float getShadow( sampler2DShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 texelSize = vec2( 1.0 ) / shadowMapSize;
				vec2 radius = shadowRadius * texelSize;
				float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
				shadow = (
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 0, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 1, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 2, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 3, 5, phi ) * radius, shadowCoord.z ) ) +
					texture( shadowMap, vec3( shadowCoord.xy + vogelDiskSample( 4, 5, phi ) * radius, shadowCoord.z ) )
				) * 0.2;
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#elif defined( SHADOWMAP_TYPE_VSM )
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				vec2 distribution = texture2D( shadowMap, shadowCoord.xy ).rg;
				float mean = distribution.x;
				float variance = distribution.y * distribution.y;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					float hard_shadow = step( mean, shadowCoord.z );
				#else
					float hard_shadow = step( shadowCoord.z, mean );
				#endif
				
				if ( hard_shadow == 1.0 ) {
					shadow = 1.0;
				} else {
					variance = max( variance, 0.0000001 );
					float d = shadowCoord.z - mean;
					float p_max = variance / ( variance + d * d );
					p_max = clamp( ( p_max - 0.3 ) / 0.65, 0.0, 1.0 );
					shadow = max( hard_shadow, p_max );
				}
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#else
		float getShadow( sampler2D shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord ) {
			float shadow = 1.0;
			shadowCoord.xyz /= shadowCoord.w;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				shadowCoord.z -= shadowBias;
			#else
				shadowCoord.z += shadowBias;
			#endif
			bool inFrustum = shadowCoord.x >= 0.0 && shadowCoord.x <= 1.0 && shadowCoord.y >= 0.0 && shadowCoord.y <= 1.0;
			bool frustumTest = inFrustum && shadowCoord.z <= 1.0;
			if ( frustumTest ) {
				float depth = texture2D( shadowMap, shadowCoord.xy ).r;
				#ifdef USE_REVERSED_DEPTH_BUFFER
					shadow = step( depth, shadowCoord.z );
				#else
					shadow = step( shadowCoord.z, depth );
				#endif
			}
			return mix( 1.0, shadow, shadowIntensity );
		}
	#endif
	#if NUM_SUN_LIGHT_SHADOWS > 0
		float getSunShadow(
			#if defined( SHADOWMAP_TYPE_PCF )
				sampler2DShadow shadowMap,
			#else
				sampler2D shadowMap,
			#endif
			SunLightShadow sunLightShadow,
			int shadowIndex
		) {
			vec4 shadowWorldPosition = vec4( vSunShadowWorldPosition.xyz + vSunShadowWorldNormal * sunLightShadow.shadowNormalBias, 1.0 );
			float viewDepth = vSunShadowWorldPosition.w;
			int cascadeOffset = shadowIndex * SUN_LIGHT_CASCADES;
			float shadow = 1.0;
			for ( int i = SUN_LIGHT_CASCADES - 1; i >= 0; i -- ) {
				vec4 cascade = sunShadowCascade[ cascadeOffset + i ];
				if ( viewDepth >= cascade.x && viewDepth < cascade.y ) {
					float cascadeShadow = getShadow(
						shadowMap,
						sunLightShadow.shadowMapSize,
						sunLightShadow.shadowIntensity,
						sunLightShadow.shadowBias,
						sunLightShadow.shadowRadius,
						sunShadowMatrix[ cascadeOffset + i ] * shadowWorldPosition
					);
					shadow = mix( cascadeShadow, shadow, smoothstep( cascade.z, cascade.y, viewDepth ) );
				}
			}
			return shadow;
		}
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
	#if defined( SHADOWMAP_TYPE_PCF )
	float getPointShadow( samplerCubeShadow shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 bd3D = normalize( lightToPosition );
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float lightDistance = length( lightToPosition );
			float depthRange = shadowCameraFar - shadowCameraNear;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				float depthA = - shadowCameraNear / depthRange - shadowBias;
				float depthB = shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#else
				float depthA = shadowCameraFar / depthRange + shadowBias;
				float depthB = - shadowCameraNear * shadowCameraFar / ( depthRange * lightDistance );
			#endif
			float texelSize = shadowRadius / shadowMapSize.x;
			vec3 absDir = abs( bd3D );
			vec3 tangent = absDir.x > absDir.z ? vec3( 0.0, 1.0, 0.0 ) : vec3( 1.0, 0.0, 0.0 );
			tangent = normalize( cross( bd3D, tangent ) );
			vec3 bitangent = cross( bd3D, tangent );
			float phi = interleavedGradientNoise( gl_FragCoord.xy ) * PI2;
			shadow = 0.0;
			for ( int i = 0; i < 5; i ++ ) {
				vec2 offset = vogelDiskSample( i, 5, phi );
				vec3 direction = bd3D + ( tangent * offset.x + bitangent * offset.y ) * texelSize;
				vec3 absDirection = abs( direction );
				float dp = depthA + depthB / max( max( absDirection.x, absDirection.y ), absDirection.z );
				shadow += texture( shadowMap, vec4( direction, dp ) );
			}
			shadow *= 0.2;
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#elif defined( SHADOWMAP_TYPE_BASIC )
	float getPointShadow( samplerCube shadowMap, vec2 shadowMapSize, float shadowIntensity, float shadowBias, float shadowRadius, vec4 shadowCoord, float shadowCameraNear, float shadowCameraFar ) {
		float shadow = 1.0;
		vec3 lightToPosition = shadowCoord.xyz;
		vec3 absVec = abs( lightToPosition );
		float viewSpaceZ = max( max( absVec.x, absVec.y ), absVec.z );
		if ( viewSpaceZ - shadowCameraFar <= 0.0 && viewSpaceZ - shadowCameraNear >= 0.0 ) {
			float dp = ( shadowCameraFar * ( viewSpaceZ - shadowCameraNear ) ) / ( viewSpaceZ * ( shadowCameraFar - shadowCameraNear ) );
			dp += shadowBias;
			vec3 bd3D = normalize( lightToPosition );
			float depth = textureCube( shadowMap, bd3D ).r;
			#ifdef USE_REVERSED_DEPTH_BUFFER
				depth = 1.0 - depth;
			#endif
			shadow = step( dp, depth );
		}
		return mix( 1.0, shadow, shadowIntensity );
	}
	#endif
	#endif
#endif`,Ob=`#if NUM_SPOT_LIGHT_COORDS > 0
	uniform mat4 spotLightMatrix[ NUM_SPOT_LIGHT_COORDS ];
	varying vec4 vSpotLightCoord[ NUM_SPOT_LIGHT_COORDS ];
#endif
#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
		varying vec4 vSunShadowWorldPosition;
		varying vec3 vSunShadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		uniform mat4 directionalShadowMatrix[ NUM_DIR_LIGHT_SHADOWS ];
		varying vec4 vDirectionalShadowCoord[ NUM_DIR_LIGHT_SHADOWS ];
		struct DirectionalLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform DirectionalLightShadow directionalLightShadows[ NUM_DIR_LIGHT_SHADOWS ];
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
		struct SpotLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
		};
		uniform SpotLightShadow spotLightShadows[ NUM_SPOT_LIGHT_SHADOWS ];
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		uniform mat4 pointShadowMatrix[ NUM_POINT_LIGHT_SHADOWS ];
		varying vec4 vPointShadowCoord[ NUM_POINT_LIGHT_SHADOWS ];
		struct PointLightShadow {
			float shadowIntensity;
			float shadowBias;
			float shadowNormalBias;
			float shadowRadius;
			vec2 shadowMapSize;
			float shadowCameraNear;
			float shadowCameraFar;
		};
		uniform PointLightShadow pointLightShadows[ NUM_POINT_LIGHT_SHADOWS ];
	#endif
#endif`,Fb=`#if ( defined( USE_SHADOWMAP ) && ( NUM_DIR_LIGHT_SHADOWS > 0 || NUM_SUN_LIGHT_SHADOWS > 0 || NUM_POINT_LIGHT_SHADOWS > 0 ) ) || ( NUM_SPOT_LIGHT_COORDS > 0 )
	#ifdef HAS_NORMAL
		vec3 shadowWorldNormal = transformNormalByInverseViewMatrix( transformedNormal, viewMatrix );
	#else
		vec3 shadowWorldNormal = vec3( 0.0 );
	#endif
	vec4 shadowWorldPosition;
#endif
#if defined( USE_SHADOWMAP )
	#if NUM_SUN_LIGHT_SHADOWS > 0
		vSunShadowWorldPosition = vec4( worldPosition.xyz, - mvPosition.z );
		vSunShadowWorldNormal = shadowWorldNormal;
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * directionalLightShadows[ i ].shadowNormalBias, 0 );
			vDirectionalShadowCoord[ i ] = directionalShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0
		#pragma unroll_loop_start
		for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
			shadowWorldPosition = worldPosition + vec4( shadowWorldNormal * pointLightShadows[ i ].shadowNormalBias, 0 );
			vPointShadowCoord[ i ] = pointShadowMatrix[ i ] * shadowWorldPosition;
		}
		#pragma unroll_loop_end
	#endif
#endif
#if NUM_SPOT_LIGHT_COORDS > 0
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_COORDS; i ++ ) {
		shadowWorldPosition = worldPosition;
		#if ( defined( USE_SHADOWMAP ) && UNROLLED_LOOP_INDEX < NUM_SPOT_LIGHT_SHADOWS )
			shadowWorldPosition.xyz += shadowWorldNormal * spotLightShadows[ i ].shadowNormalBias;
		#endif
		vSpotLightCoord[ i ] = spotLightMatrix[ i ] * shadowWorldPosition;
	}
	#pragma unroll_loop_end
#endif`,Bb=`float getShadowMask() {
	float shadow = 1.0;
	#ifdef USE_SHADOWMAP
	#if NUM_SUN_LIGHT_SHADOWS > 0
	SunLightShadow sunLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SUN_LIGHT_SHADOWS; i ++ ) {
		sunLight = sunLightShadows[ i ];
		shadow *= receiveShadow ? getSunShadow( sunShadowMap[ i ], sunLight, UNROLLED_LOOP_INDEX ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_DIR_LIGHT_SHADOWS > 0
	DirectionalLightShadow directionalLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_DIR_LIGHT_SHADOWS; i ++ ) {
		directionalLight = directionalLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( directionalShadowMap[ i ], directionalLight.shadowMapSize, directionalLight.shadowIntensity, directionalLight.shadowBias, directionalLight.shadowRadius, vDirectionalShadowCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_SPOT_LIGHT_SHADOWS > 0
	SpotLightShadow spotLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_SPOT_LIGHT_SHADOWS; i ++ ) {
		spotLight = spotLightShadows[ i ];
		shadow *= receiveShadow ? getShadow( spotShadowMap[ i ], spotLight.shadowMapSize, spotLight.shadowIntensity, spotLight.shadowBias, spotLight.shadowRadius, vSpotLightCoord[ i ] ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#if NUM_POINT_LIGHT_SHADOWS > 0 && ( defined( SHADOWMAP_TYPE_PCF ) || defined( SHADOWMAP_TYPE_BASIC ) )
	PointLightShadow pointLight;
	#pragma unroll_loop_start
	for ( int i = 0; i < NUM_POINT_LIGHT_SHADOWS; i ++ ) {
		pointLight = pointLightShadows[ i ];
		shadow *= receiveShadow ? getPointShadow( pointShadowMap[ i ], pointLight.shadowMapSize, pointLight.shadowIntensity, pointLight.shadowBias, pointLight.shadowRadius, vPointShadowCoord[ i ], pointLight.shadowCameraNear, pointLight.shadowCameraFar ) : 1.0;
	}
	#pragma unroll_loop_end
	#endif
	#endif
	return shadow;
}`,kb=`#ifdef USE_SKINNING
	mat4 boneMatX = getBoneMatrix( skinIndex.x );
	mat4 boneMatY = getBoneMatrix( skinIndex.y );
	mat4 boneMatZ = getBoneMatrix( skinIndex.z );
	mat4 boneMatW = getBoneMatrix( skinIndex.w );
#endif`,zb=`#ifdef USE_SKINNING
	uniform mat4 bindMatrix;
	uniform mat4 bindMatrixInverse;
	uniform highp sampler2D boneTexture;
	mat4 getBoneMatrix( const in float i ) {
		int size = textureSize( boneTexture, 0 ).x;
		int j = int( i ) * 4;
		int x = j % size;
		int y = j / size;
		vec4 v1 = texelFetch( boneTexture, ivec2( x, y ), 0 );
		vec4 v2 = texelFetch( boneTexture, ivec2( x + 1, y ), 0 );
		vec4 v3 = texelFetch( boneTexture, ivec2( x + 2, y ), 0 );
		vec4 v4 = texelFetch( boneTexture, ivec2( x + 3, y ), 0 );
		return mat4( v1, v2, v3, v4 );
	}
#endif`,Gb=`#ifdef USE_SKINNING
	vec4 skinVertex = bindMatrix * vec4( transformed, 1.0 );
	vec4 skinned = vec4( 0.0 );
	skinned += boneMatX * skinVertex * skinWeight.x;
	skinned += boneMatY * skinVertex * skinWeight.y;
	skinned += boneMatZ * skinVertex * skinWeight.z;
	skinned += boneMatW * skinVertex * skinWeight.w;
	transformed = ( bindMatrixInverse * skinned ).xyz;
#endif`,Hb=`#ifdef USE_SKINNING
	mat4 skinMatrix = mat4( 0.0 );
	skinMatrix += skinWeight.x * boneMatX;
	skinMatrix += skinWeight.y * boneMatY;
	skinMatrix += skinWeight.z * boneMatZ;
	skinMatrix += skinWeight.w * boneMatW;
	skinMatrix = bindMatrixInverse * skinMatrix * bindMatrix;
	objectNormal = vec4( skinMatrix * vec4( objectNormal, 0.0 ) ).xyz;
	#ifdef USE_TANGENT
		objectTangent = vec4( skinMatrix * vec4( objectTangent, 0.0 ) ).xyz;
	#endif
#endif`,Vb=`float specularStrength;
#ifdef USE_SPECULARMAP
	vec4 texelSpecular = texture2D( specularMap, vSpecularMapUv );
	specularStrength = texelSpecular.r;
#else
	specularStrength = 1.0;
#endif`,Wb=`#ifdef USE_SPECULARMAP
	uniform sampler2D specularMap;
#endif`,Xb=`#if defined( TONE_MAPPING )
	gl_FragColor.rgb = toneMapping( gl_FragColor.rgb );
#endif`,qb=`#ifndef saturate
#define saturate( a ) clamp( a, 0.0, 1.0 )
#endif
uniform float toneMappingExposure;
vec3 LinearToneMapping( vec3 color ) {
	return saturate( toneMappingExposure * color );
}
vec3 ReinhardToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	return saturate( color / ( vec3( 1.0 ) + color ) );
}
vec3 CineonToneMapping( vec3 color ) {
	color *= toneMappingExposure;
	color = max( vec3( 0.0 ), color - 0.004 );
	return pow( ( color * ( 6.2 * color + 0.5 ) ) / ( color * ( 6.2 * color + 1.7 ) + 0.06 ), vec3( 2.2 ) );
}
vec3 RRTAndODTFit( vec3 v ) {
	vec3 a = v * ( v + 0.0245786 ) - 0.000090537;
	vec3 b = v * ( 0.983729 * v + 0.4329510 ) + 0.238081;
	return a / b;
}
vec3 ACESFilmicToneMapping( vec3 color ) {
	const mat3 ACESInputMat = mat3(
		vec3( 0.59719, 0.07600, 0.02840 ),		vec3( 0.35458, 0.90834, 0.13383 ),
		vec3( 0.04823, 0.01566, 0.83777 )
	);
	const mat3 ACESOutputMat = mat3(
		vec3(  1.60475, -0.10208, -0.00327 ),		vec3( -0.53108,  1.10813, -0.07276 ),
		vec3( -0.07367, -0.00605,  1.07602 )
	);
	color *= toneMappingExposure / 0.6;
	color = ACESInputMat * color;
	color = RRTAndODTFit( color );
	color = ACESOutputMat * color;
	return saturate( color );
}
const mat3 LINEAR_REC2020_TO_LINEAR_SRGB = mat3(
	vec3( 1.6605, - 0.1246, - 0.0182 ),
	vec3( - 0.5876, 1.1329, - 0.1006 ),
	vec3( - 0.0728, - 0.0083, 1.1187 )
);
const mat3 LINEAR_SRGB_TO_LINEAR_REC2020 = mat3(
	vec3( 0.6274, 0.0691, 0.0164 ),
	vec3( 0.3293, 0.9195, 0.0880 ),
	vec3( 0.0433, 0.0113, 0.8956 )
);
vec3 agxDefaultContrastApprox( vec3 x ) {
	vec3 x2 = x * x;
	vec3 x4 = x2 * x2;
	return + 15.5 * x4 * x2
		- 40.14 * x4 * x
		+ 31.96 * x4
		- 6.868 * x2 * x
		+ 0.4298 * x2
		+ 0.1191 * x
		- 0.00232;
}
vec3 AgXToneMapping( vec3 color ) {
	const mat3 AgXInsetMatrix = mat3(
		vec3( 0.856627153315983, 0.137318972929847, 0.11189821299995 ),
		vec3( 0.0951212405381588, 0.761241990602591, 0.0767994186031903 ),
		vec3( 0.0482516061458583, 0.101439036467562, 0.811302368396859 )
	);
	const mat3 AgXOutsetMatrix = mat3(
		vec3( 1.1271005818144368, - 0.1413297634984383, - 0.14132976349843826 ),
		vec3( - 0.11060664309660323, 1.157823702216272, - 0.11060664309660294 ),
		vec3( - 0.016493938717834573, - 0.016493938717834257, 1.2519364065950405 )
	);
	const float AgxMinEv = - 12.47393;	const float AgxMaxEv = 4.026069;
	color *= toneMappingExposure;
	color = LINEAR_SRGB_TO_LINEAR_REC2020 * color;
	color = AgXInsetMatrix * color;
	color = max( color, 1e-10 );	color = log2( color );
	color = ( color - AgxMinEv ) / ( AgxMaxEv - AgxMinEv );
	color = clamp( color, 0.0, 1.0 );
	color = agxDefaultContrastApprox( color );
	color = AgXOutsetMatrix * color;
	color = pow( max( vec3( 0.0 ), color ), vec3( 2.2 ) );
	color = LINEAR_REC2020_TO_LINEAR_SRGB * color;
	color = clamp( color, 0.0, 1.0 );
	return color;
}
vec3 NeutralToneMapping( vec3 color ) {
	const float StartCompression = 0.8 - 0.04;
	const float Desaturation = 0.15;
	color *= toneMappingExposure;
	float x = min( color.r, min( color.g, color.b ) );
	float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
	color -= offset;
	float peak = max( color.r, max( color.g, color.b ) );
	if ( peak < StartCompression ) return color;
	float d = 1. - StartCompression;
	float newPeak = 1. - d * d / ( peak + d - StartCompression );
	color *= newPeak / peak;
	float g = 1. - 1. / ( Desaturation * ( peak - newPeak ) + 1. );
	return mix( color, vec3( newPeak ), g );
}
vec3 CustomToneMapping( vec3 color ) { return color; }`,Yb=`#ifdef USE_TRANSMISSION
	material.transmission = transmission;
	material.transmissionAlpha = 1.0;
	material.thickness = thickness;
	material.attenuationDistance = attenuationDistance;
	material.attenuationColor = attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		material.transmission *= texture2D( transmissionMap, vTransmissionMapUv ).r;
	#endif
	#ifdef USE_THICKNESSMAP
		material.thickness *= texture2D( thicknessMap, vThicknessMapUv ).g;
	#endif
	vec3 pos = vWorldPosition;
	vec3 v = normalize( cameraPosition - pos );
	vec3 n = transformNormalByInverseViewMatrix( normal, viewMatrix );
	vec4 transmitted = getIBLVolumeRefraction(
		n, v, material.roughness, material.diffuseContribution, material.specularColorBlended, material.specularF90,
		pos, modelMatrix, viewMatrix, projectionMatrix, material.dispersion, material.ior, material.thickness,
		material.attenuationColor, material.attenuationDistance );
	material.transmissionAlpha = mix( material.transmissionAlpha, transmitted.a, material.transmission );
	totalDiffuse = mix( totalDiffuse, transmitted.rgb, material.transmission );
#endif`,$b=`#ifdef USE_TRANSMISSION
	uniform float transmission;
	uniform float thickness;
	uniform float attenuationDistance;
	uniform vec3 attenuationColor;
	#ifdef USE_TRANSMISSIONMAP
		uniform sampler2D transmissionMap;
	#endif
	#ifdef USE_THICKNESSMAP
		uniform sampler2D thicknessMap;
	#endif
	uniform vec2 transmissionSamplerSize;
	uniform sampler2D transmissionSamplerMap;
	uniform mat4 modelMatrix;
	uniform mat4 projectionMatrix;
	varying vec3 vWorldPosition;
	float w0( float a ) {
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - a + 3.0 ) - 3.0 ) + 1.0 );
	}
	float w1( float a ) {
		return ( 1.0 / 6.0 ) * ( a *  a * ( 3.0 * a - 6.0 ) + 4.0 );
	}
	float w2( float a ){
		return ( 1.0 / 6.0 ) * ( a * ( a * ( - 3.0 * a + 3.0 ) + 3.0 ) + 1.0 );
	}
	float w3( float a ) {
		return ( 1.0 / 6.0 ) * ( a * a * a );
	}
	float g0( float a ) {
		return w0( a ) + w1( a );
	}
	float g1( float a ) {
		return w2( a ) + w3( a );
	}
	float h0( float a ) {
		return - 1.0 + w1( a ) / ( w0( a ) + w1( a ) );
	}
	float h1( float a ) {
		return 1.0 + w3( a ) / ( w2( a ) + w3( a ) );
	}
	vec4 bicubic( sampler2D tex, vec2 uv, vec4 texelSize, float lod ) {
		uv = uv * texelSize.zw + 0.5;
		vec2 iuv = floor( uv );
		vec2 fuv = fract( uv );
		float g0x = g0( fuv.x );
		float g1x = g1( fuv.x );
		float h0x = h0( fuv.x );
		float h1x = h1( fuv.x );
		float h0y = h0( fuv.y );
		float h1y = h1( fuv.y );
		vec2 p0 = ( vec2( iuv.x + h0x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p1 = ( vec2( iuv.x + h1x, iuv.y + h0y ) - 0.5 ) * texelSize.xy;
		vec2 p2 = ( vec2( iuv.x + h0x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		vec2 p3 = ( vec2( iuv.x + h1x, iuv.y + h1y ) - 0.5 ) * texelSize.xy;
		return g0( fuv.y ) * ( g0x * textureLod( tex, p0, lod ) + g1x * textureLod( tex, p1, lod ) ) +
			g1( fuv.y ) * ( g0x * textureLod( tex, p2, lod ) + g1x * textureLod( tex, p3, lod ) );
	}
	vec4 textureBicubic( sampler2D sampler, vec2 uv, float lod ) {
		vec2 fLodSize = vec2( textureSize( sampler, int( lod ) ) );
		vec2 cLodSize = vec2( textureSize( sampler, int( lod + 1.0 ) ) );
		vec2 fLodSizeInv = 1.0 / fLodSize;
		vec2 cLodSizeInv = 1.0 / cLodSize;
		vec4 fSample = bicubic( sampler, uv, vec4( fLodSizeInv, fLodSize ), floor( lod ) );
		vec4 cSample = bicubic( sampler, uv, vec4( cLodSizeInv, cLodSize ), ceil( lod ) );
		return mix( fSample, cSample, fract( lod ) );
	}
	vec3 getVolumeTransmissionRay( const in vec3 n, const in vec3 v, const in float thickness, const in float ior, const in mat4 modelMatrix ) {
		vec3 refractionVector = refract( - v, normalize( n ), 1.0 / ior );
		vec3 modelScale;
		modelScale.x = length( vec3( modelMatrix[ 0 ].xyz ) );
		modelScale.y = length( vec3( modelMatrix[ 1 ].xyz ) );
		modelScale.z = length( vec3( modelMatrix[ 2 ].xyz ) );
		return normalize( refractionVector ) * thickness * modelScale;
	}
	float applyIorToRoughness( const in float roughness, const in float ior ) {
		return roughness * clamp( ior * 2.0 - 2.0, 0.0, 1.0 );
	}
	vec4 getTransmissionSample( const in vec2 fragCoord, const in float roughness, const in float ior ) {
		float lod = log2( transmissionSamplerSize.x ) * applyIorToRoughness( roughness, ior );
		return textureBicubic( transmissionSamplerMap, fragCoord.xy, lod );
	}
	vec3 volumeAttenuation( const in float transmissionDistance, const in vec3 attenuationColor, const in float attenuationDistance ) {
		if ( isinf( attenuationDistance ) ) {
			return vec3( 1.0 );
		} else {
			vec3 attenuationCoefficient = -log( attenuationColor ) / attenuationDistance;
			vec3 transmittance = exp( - attenuationCoefficient * transmissionDistance );			return transmittance;
		}
	}
	vec4 getIBLVolumeRefraction( const in vec3 n, const in vec3 v, const in float roughness, const in vec3 diffuseColor,
		const in vec3 specularColor, const in float specularF90, const in vec3 position, const in mat4 modelMatrix,
		const in mat4 viewMatrix, const in mat4 projMatrix, const in float dispersion, const in float ior, const in float thickness,
		const in vec3 attenuationColor, const in float attenuationDistance ) {
		vec4 transmittedLight;
		vec3 transmittance;
		#ifdef USE_DISPERSION
			float halfSpread = ( ior - 1.0 ) * 0.025 * dispersion;
			vec3 iors = vec3( ior - halfSpread, ior, ior + halfSpread );
			for ( int i = 0; i < 3; i ++ ) {
				vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, iors[ i ], modelMatrix );
				vec3 refractedRayExit = position + transmissionRay;
				vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
				vec2 refractionCoords = ndcPos.xy / ndcPos.w;
				refractionCoords += 1.0;
				refractionCoords /= 2.0;
				vec4 transmissionSample = getTransmissionSample( refractionCoords, roughness, iors[ i ] );
				transmittedLight[ i ] = transmissionSample[ i ];
				transmittedLight.a += transmissionSample.a;
				transmittance[ i ] = diffuseColor[ i ] * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance )[ i ];
			}
			transmittedLight.a /= 3.0;
		#else
			vec3 transmissionRay = getVolumeTransmissionRay( n, v, thickness, ior, modelMatrix );
			vec3 refractedRayExit = position + transmissionRay;
			vec4 ndcPos = projMatrix * viewMatrix * vec4( refractedRayExit, 1.0 );
			vec2 refractionCoords = ndcPos.xy / ndcPos.w;
			refractionCoords += 1.0;
			refractionCoords /= 2.0;
			transmittedLight = getTransmissionSample( refractionCoords, roughness, ior );
			transmittance = diffuseColor * volumeAttenuation( length( transmissionRay ), attenuationColor, attenuationDistance );
		#endif
		vec3 attenuatedColor = transmittance * transmittedLight.rgb;
		vec3 F = EnvironmentBRDF( n, v, specularColor, specularF90, roughness );
		float transmittanceFactor = ( transmittance.r + transmittance.g + transmittance.b ) / 3.0;
		return vec4( ( 1.0 - F ) * attenuatedColor, 1.0 - ( 1.0 - transmittedLight.a ) * transmittanceFactor );
	}
#endif`,Zb=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_SPECULARMAP
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,Kb=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	varying vec2 vUv;
#endif
#ifdef USE_MAP
	uniform mat3 mapTransform;
	varying vec2 vMapUv;
#endif
#ifdef USE_ALPHAMAP
	uniform mat3 alphaMapTransform;
	varying vec2 vAlphaMapUv;
#endif
#ifdef USE_LIGHTMAP
	uniform mat3 lightMapTransform;
	varying vec2 vLightMapUv;
#endif
#ifdef USE_AOMAP
	uniform mat3 aoMapTransform;
	varying vec2 vAoMapUv;
#endif
#ifdef USE_BUMPMAP
	uniform mat3 bumpMapTransform;
	varying vec2 vBumpMapUv;
#endif
#ifdef USE_NORMALMAP
	uniform mat3 normalMapTransform;
	varying vec2 vNormalMapUv;
#endif
#ifdef USE_DISPLACEMENTMAP
	uniform mat3 displacementMapTransform;
	varying vec2 vDisplacementMapUv;
#endif
#ifdef USE_EMISSIVEMAP
	uniform mat3 emissiveMapTransform;
	varying vec2 vEmissiveMapUv;
#endif
#ifdef USE_METALNESSMAP
	uniform mat3 metalnessMapTransform;
	varying vec2 vMetalnessMapUv;
#endif
#ifdef USE_ROUGHNESSMAP
	uniform mat3 roughnessMapTransform;
	varying vec2 vRoughnessMapUv;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	uniform mat3 diffuseRoughnessMapTransform;
	varying vec2 vDiffuseRoughnessMapUv;
#endif
#ifdef USE_ANISOTROPYMAP
	uniform mat3 anisotropyMapTransform;
	varying vec2 vAnisotropyMapUv;
#endif
#ifdef USE_CLEARCOATMAP
	uniform mat3 clearcoatMapTransform;
	varying vec2 vClearcoatMapUv;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	uniform mat3 clearcoatNormalMapTransform;
	varying vec2 vClearcoatNormalMapUv;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	uniform mat3 clearcoatRoughnessMapTransform;
	varying vec2 vClearcoatRoughnessMapUv;
#endif
#ifdef USE_SHEEN_COLORMAP
	uniform mat3 sheenColorMapTransform;
	varying vec2 vSheenColorMapUv;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	uniform mat3 sheenRoughnessMapTransform;
	varying vec2 vSheenRoughnessMapUv;
#endif
#ifdef USE_IRIDESCENCEMAP
	uniform mat3 iridescenceMapTransform;
	varying vec2 vIridescenceMapUv;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	uniform mat3 iridescenceThicknessMapTransform;
	varying vec2 vIridescenceThicknessMapUv;
#endif
#ifdef USE_SPECULARMAP
	uniform mat3 specularMapTransform;
	varying vec2 vSpecularMapUv;
#endif
#ifdef USE_SPECULAR_COLORMAP
	uniform mat3 specularColorMapTransform;
	varying vec2 vSpecularColorMapUv;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	uniform mat3 specularIntensityMapTransform;
	varying vec2 vSpecularIntensityMapUv;
#endif
#ifdef USE_TRANSMISSIONMAP
	uniform mat3 transmissionMapTransform;
	varying vec2 vTransmissionMapUv;
#endif
#ifdef USE_THICKNESSMAP
	uniform mat3 thicknessMapTransform;
	varying vec2 vThicknessMapUv;
#endif`,Jb=`#if defined( USE_UV ) || defined( USE_ANISOTROPY )
	vUv = vec3( uv, 1 ).xy;
#endif
#ifdef USE_MAP
	vMapUv = ( mapTransform * vec3( MAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ALPHAMAP
	vAlphaMapUv = ( alphaMapTransform * vec3( ALPHAMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_LIGHTMAP
	vLightMapUv = ( lightMapTransform * vec3( LIGHTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_AOMAP
	vAoMapUv = ( aoMapTransform * vec3( AOMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_BUMPMAP
	vBumpMapUv = ( bumpMapTransform * vec3( BUMPMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_NORMALMAP
	vNormalMapUv = ( normalMapTransform * vec3( NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DISPLACEMENTMAP
	vDisplacementMapUv = ( displacementMapTransform * vec3( DISPLACEMENTMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_EMISSIVEMAP
	vEmissiveMapUv = ( emissiveMapTransform * vec3( EMISSIVEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_METALNESSMAP
	vMetalnessMapUv = ( metalnessMapTransform * vec3( METALNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ROUGHNESSMAP
	vRoughnessMapUv = ( roughnessMapTransform * vec3( ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_DIFFUSE_ROUGHNESSMAP
	vDiffuseRoughnessMapUv = ( diffuseRoughnessMapTransform * vec3( DIFFUSE_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_ANISOTROPYMAP
	vAnisotropyMapUv = ( anisotropyMapTransform * vec3( ANISOTROPYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOATMAP
	vClearcoatMapUv = ( clearcoatMapTransform * vec3( CLEARCOATMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_NORMALMAP
	vClearcoatNormalMapUv = ( clearcoatNormalMapTransform * vec3( CLEARCOAT_NORMALMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_CLEARCOAT_ROUGHNESSMAP
	vClearcoatRoughnessMapUv = ( clearcoatRoughnessMapTransform * vec3( CLEARCOAT_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCEMAP
	vIridescenceMapUv = ( iridescenceMapTransform * vec3( IRIDESCENCEMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_IRIDESCENCE_THICKNESSMAP
	vIridescenceThicknessMapUv = ( iridescenceThicknessMapTransform * vec3( IRIDESCENCE_THICKNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_COLORMAP
	vSheenColorMapUv = ( sheenColorMapTransform * vec3( SHEEN_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SHEEN_ROUGHNESSMAP
	vSheenRoughnessMapUv = ( sheenRoughnessMapTransform * vec3( SHEEN_ROUGHNESSMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULARMAP
	vSpecularMapUv = ( specularMapTransform * vec3( SPECULARMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_COLORMAP
	vSpecularColorMapUv = ( specularColorMapTransform * vec3( SPECULAR_COLORMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_SPECULAR_INTENSITYMAP
	vSpecularIntensityMapUv = ( specularIntensityMapTransform * vec3( SPECULAR_INTENSITYMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_TRANSMISSIONMAP
	vTransmissionMapUv = ( transmissionMapTransform * vec3( TRANSMISSIONMAP_UV, 1 ) ).xy;
#endif
#ifdef USE_THICKNESSMAP
	vThicknessMapUv = ( thicknessMapTransform * vec3( THICKNESSMAP_UV, 1 ) ).xy;
#endif`,jb=`#if defined( USE_ENVMAP ) || defined( DISTANCE ) || defined ( USE_SHADOWMAP ) || defined ( USE_TRANSMISSION ) || NUM_SPOT_LIGHT_COORDS > 0
	vec4 worldPosition = vec4( transformed, 1.0 );
	#ifdef USE_BATCHING
		worldPosition = batchingMatrix * worldPosition;
	#endif
	#ifdef USE_INSTANCING
		worldPosition = instanceMatrix * worldPosition;
	#endif
	worldPosition = modelMatrix * worldPosition;
#endif`,Qb=`varying vec2 vUv;
uniform mat3 uvTransform;
void main() {
	vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	gl_Position = vec4( position.xy, 1.0, 1.0 );
}`,eM=`uniform sampler2D t2D;
uniform float backgroundIntensity;
varying vec2 vUv;
void main() {
	vec4 texColor = texture2D( t2D, vUv );
	#ifdef DECODE_VIDEO_TEXTURE
		texColor = vec4( mix( pow( texColor.rgb * 0.9478672986 + vec3( 0.0521327014 ), vec3( 2.4 ) ), texColor.rgb * 0.0773993808, vec3( lessThanEqual( texColor.rgb, vec3( 0.04045 ) ) ) ), texColor.w );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,tM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,nM=`uniform float backgroundBlurriness;
uniform float backgroundIntensity;
uniform mat3 backgroundRotation;
varying vec3 vWorldDirection;
#include <envmap_common_pars_fragment>
void main() {
	#ifdef ENVMAP_TYPE_PMREM
		vec4 texColor = textureLod( envMap, backgroundRotation * vWorldDirection, roughnessToMip( backgroundBlurriness ) );
	#else
		vec4 texColor = textureCube( envMap, backgroundRotation * vWorldDirection );
	#endif
	texColor.rgb *= backgroundIntensity;
	gl_FragColor = texColor;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,iM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
	gl_Position.z = gl_Position.w;
}`,sM=`uniform samplerCube tCube;
uniform float tFlip;
uniform float opacity;
varying vec3 vWorldDirection;
void main() {
	vec4 texColor = textureCube( tCube, vec3( tFlip * vWorldDirection.x, vWorldDirection.yz ) );
	gl_FragColor = texColor;
	gl_FragColor.a *= opacity;
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,rM=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
varying vec2 vHighPrecisionZW;
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vHighPrecisionZW = gl_Position.zw;
}`,oM=`#if DEPTH_PACKING == 3200
	uniform float opacity;
#endif
#include <common>
#include <packing>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
varying vec2 vHighPrecisionZW;
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#if DEPTH_PACKING == 3200
		diffuseColor.a = opacity;
	#endif
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <logdepthbuf_fragment>
	#ifdef USE_REVERSED_DEPTH_BUFFER
		float fragCoordZ = vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ];
	#else
		float fragCoordZ = 0.5 * vHighPrecisionZW[ 0 ] / vHighPrecisionZW[ 1 ] + 0.5;
	#endif
	#if DEPTH_PACKING == 3200
		gl_FragColor = vec4( vec3( 1.0 - fragCoordZ ), opacity );
	#elif DEPTH_PACKING == 3201
		gl_FragColor = packDepthToRGBA( fragCoordZ );
	#elif DEPTH_PACKING == 3202
		gl_FragColor = vec4( packDepthToRGB( fragCoordZ ), 1.0 );
	#elif DEPTH_PACKING == 3203
		gl_FragColor = vec4( packDepthToRG( fragCoordZ ), 0.0, 1.0 );
	#endif
}`,aM=`#define DISTANCE
varying vec3 vWorldPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <skinbase_vertex>
	#include <morphinstance_vertex>
	#ifdef USE_DISPLACEMENTMAP
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <worldpos_vertex>
	#include <clipping_planes_vertex>
	vWorldPosition = worldPosition.xyz;
}`,lM=`#define DISTANCE
uniform vec3 referencePosition;
uniform float nearDistance;
uniform float farDistance;
varying vec3 vWorldPosition;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 1.0 );
	#include <clipping_planes_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	float dist = length( vWorldPosition - referencePosition );
	dist = ( dist - nearDistance ) / ( farDistance - nearDistance );
	dist = saturate( dist );
	gl_FragColor = vec4( dist, 0.0, 0.0, 1.0 );
}`,cM=`varying vec3 vWorldDirection;
#include <common>
void main() {
	vWorldDirection = transformDirection( position, modelMatrix );
	#include <begin_vertex>
	#include <project_vertex>
}`,hM=`uniform sampler2D tEquirect;
varying vec3 vWorldDirection;
#include <common>
void main() {
	vec3 direction = normalize( vWorldDirection );
	vec2 sampleUV = equirectUv( direction );
	gl_FragColor = texture2D( tEquirect, sampleUV );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
}`,uM=`uniform float scale;
attribute float lineDistance;
varying float vLineDistance;
#include <common>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	vLineDistance = scale * lineDistance;
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,fM=`uniform vec3 diffuse;
uniform float opacity;
uniform float dashSize;
uniform float totalSize;
varying float vLineDistance;
#include <common>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	if ( mod( vLineDistance, totalSize ) > dashSize ) {
		discard;
	}
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,dM=`#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#if defined ( USE_ENVMAP ) || defined ( USE_SKINNING )
		#include <beginnormal_vertex>
		#include <morphnormal_vertex>
		#include <skinbase_vertex>
		#include <skinnormal_vertex>
		#include <defaultnormal_vertex>
	#endif
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <fog_vertex>
}`,pM=`uniform vec3 diffuse;
uniform float opacity;
#ifndef FLAT_SHADED
	varying vec3 vNormal;
#endif
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <fog_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	#ifdef USE_LIGHTMAP
		vec4 lightMapTexel = texture2D( lightMap, vLightMapUv );
		reflectedLight.indirectDiffuse += lightMapTexel.rgb * lightMapIntensity * RECIPROCAL_PI;
	#else
		reflectedLight.indirectDiffuse += vec3( 1.0 );
	#endif
	#include <aomap_fragment>
	reflectedLight.indirectDiffuse *= diffuseColor.rgb;
	vec3 outgoingLight = reflectedLight.indirectDiffuse;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,mM=`#define LAMBERT
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,gM=`#define LAMBERT
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_lambert_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_lambert_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,_M=`#define MATCAP
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <color_pars_vertex>
#include <displacementmap_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
	vViewPosition = - mvPosition.xyz;
}`,xM=`#define MATCAP
uniform vec3 diffuse;
uniform float opacity;
uniform sampler2D matcap;
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	vec3 viewDir = normalize( vViewPosition );
	vec3 x = normalize( vec3( viewDir.z, 0.0, - viewDir.x ) );
	vec3 y = cross( viewDir, x );
	vec2 uv = vec2( dot( x, normal ), dot( y, normal ) ) * 0.495 + 0.5;
	#ifdef USE_MATCAP
		vec4 matcapColor = texture2D( matcap, uv );
	#else
		vec4 matcapColor = vec4( vec3( mix( 0.2, 0.8, uv.y ) ), 1.0 );
	#endif
	vec3 outgoingLight = diffuseColor.rgb * matcapColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,yM=`#define NORMAL
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	vViewPosition = - mvPosition.xyz;
#endif
}`,vM=`#define NORMAL
uniform float opacity;
#if defined( FLAT_SHADED ) || defined( USE_BUMPMAP ) || defined( USE_NORMALMAP_TANGENTSPACE )
	varying vec3 vViewPosition;
#endif
#include <uv_pars_fragment>
#include <normal_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( 0.0, 0.0, 0.0, opacity );
	#include <clipping_planes_fragment>
	#include <logdepthbuf_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	gl_FragColor = vec4( normalize( normal ) * 0.5 + 0.5, diffuseColor.a );
	#ifdef OPAQUE
		gl_FragColor.a = 1.0;
	#endif
}`,SM=`#define PHONG
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <envmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <envmap_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,bM=`#define PHONG
uniform vec3 diffuse;
uniform vec3 emissive;
uniform vec3 specular;
uniform float shininess;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_phong_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <specularmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <specularmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_phong_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + reflectedLight.directSpecular + reflectedLight.indirectSpecular + totalEmissiveRadiance;
	#include <envmap_fragment>
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,MM=`#define STANDARD
varying vec3 vViewPosition;
#ifdef USE_TRANSMISSION
	varying vec3 vWorldPosition;
#endif
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
#ifdef USE_TRANSMISSION
	vWorldPosition = worldPosition.xyz;
#endif
}`,wM=`#define STANDARD
#ifdef PHYSICAL
	#define IOR
	#define USE_SPECULAR
#endif
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float roughness;
uniform float metalness;
uniform float opacity;
#ifdef IOR
	uniform float ior;
#endif
#ifdef USE_SPECULAR
	uniform float specularIntensity;
	uniform vec3 specularColor;
	#ifdef USE_SPECULAR_COLORMAP
		uniform sampler2D specularColorMap;
	#endif
	#ifdef USE_SPECULAR_INTENSITYMAP
		uniform sampler2D specularIntensityMap;
	#endif
#endif
#ifdef USE_CLEARCOAT
	uniform float clearcoat;
	uniform float clearcoatRoughness;
#endif
#ifdef USE_DIFFUSE_ROUGHNESS
	uniform float diffuseRoughness;
	#ifdef USE_DIFFUSE_ROUGHNESSMAP
		uniform sampler2D diffuseRoughnessMap;
	#endif
#endif
#ifdef USE_DISPERSION
	uniform float dispersion;
#endif
#ifdef USE_RETROREFLECTION
	uniform float retroreflectivity;
#endif
#ifdef USE_IRIDESCENCE
	uniform float iridescence;
	uniform float iridescenceIOR;
	uniform float iridescenceThicknessMinimum;
	uniform float iridescenceThicknessMaximum;
#endif
#ifdef USE_SHEEN
	uniform vec3 sheenColor;
	uniform float sheenRoughness;
	#ifdef USE_SHEEN_COLORMAP
		uniform sampler2D sheenColorMap;
	#endif
	#ifdef USE_SHEEN_ROUGHNESSMAP
		uniform sampler2D sheenRoughnessMap;
	#endif
#endif
#ifdef USE_ANISOTROPY
	uniform vec2 anisotropyVector;
	#ifdef USE_ANISOTROPYMAP
		uniform sampler2D anisotropyMap;
	#endif
#endif
varying vec3 vViewPosition;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <iridescence_fragment>
#include <envmap_common_pars_fragment>
#include <envmap_physical_pars_fragment>
#include <fog_pars_fragment>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_physical_pars_fragment>
#include <transmission_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <clearcoat_pars_fragment>
#include <iridescence_pars_fragment>
#include <roughnessmap_pars_fragment>
#include <metalnessmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <roughnessmap_fragment>
	#include <metalnessmap_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <clearcoat_normal_fragment_begin>
	#include <clearcoat_normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_physical_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 totalDiffuse = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse;
	vec3 totalSpecular = reflectedLight.directSpecular + reflectedLight.indirectSpecular;
	#include <transmission_fragment>
	vec3 outgoingLight = totalDiffuse + totalSpecular + totalEmissiveRadiance;
	#ifdef USE_SHEEN
 
		outgoingLight = outgoingLight + sheenSpecularDirect + sheenSpecularIndirect;
 
 	#endif
	#ifdef USE_CLEARCOAT
		float dotNVcc = saturate( dot( geometryClearcoatNormal, geometryViewDir ) );
		vec3 Fcc = F_Schlick( material.clearcoatF0, material.clearcoatF90, dotNVcc );
		outgoingLight = outgoingLight * ( 1.0 - material.clearcoat * Fcc ) + ( clearcoatSpecularDirect + clearcoatSpecularIndirect ) * material.clearcoat;
	#endif
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,EM=`#define TOON
varying vec3 vViewPosition;
#include <common>
#include <batching_pars_vertex>
#include <uv_pars_vertex>
#include <displacementmap_pars_vertex>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <normal_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <shadowmap_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <normal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <displacementmap_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	vViewPosition = - mvPosition.xyz;
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,TM=`#define TOON
uniform vec3 diffuse;
uniform vec3 emissive;
uniform float opacity;
#include <common>
#include <dithering_pars_fragment>
#include <color_pars_fragment>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <aomap_pars_fragment>
#include <lightmap_pars_fragment>
#include <emissivemap_pars_fragment>
#include <gradientmap_pars_fragment>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <normal_pars_fragment>
#include <lights_toon_pars_fragment>
#include <shadowmap_pars_fragment>
#include <bumpmap_pars_fragment>
#include <normalmap_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	ReflectedLight reflectedLight = ReflectedLight( vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ), vec3( 0.0 ) );
	vec3 totalEmissiveRadiance = emissive;
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <color_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	#include <normal_fragment_begin>
	#include <normal_fragment_maps>
	#include <emissivemap_fragment>
	#include <lights_toon_fragment>
	#include <lights_fragment_begin>
	#include <lights_fragment_maps>
	#include <lights_fragment_end>
	#include <aomap_fragment>
	vec3 outgoingLight = reflectedLight.directDiffuse + reflectedLight.indirectDiffuse + totalEmissiveRadiance;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
	#include <dithering_fragment>
}`,AM=`uniform float size;
uniform float scale;
#include <common>
#include <color_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
#ifdef USE_POINTS_UV
	varying vec2 vUv;
	uniform mat3 uvTransform;
#endif
void main() {
	#ifdef USE_POINTS_UV
		vUv = ( uvTransform * vec3( uv, 1 ) ).xy;
	#endif
	#include <color_vertex>
	#include <morphinstance_vertex>
	#include <morphcolor_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <project_vertex>
	gl_PointSize = size;
	#ifdef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) gl_PointSize *= ( scale / - mvPosition.z );
	#endif
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <worldpos_vertex>
	#include <fog_vertex>
}`,RM=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <color_pars_fragment>
#include <map_particle_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_particle_fragment>
	#include <color_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,CM=`#include <common>
#include <batching_pars_vertex>
#include <fog_pars_vertex>
#include <morphtarget_pars_vertex>
#include <skinning_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <shadowmap_pars_vertex>
void main() {
	#include <batching_vertex>
	#include <beginnormal_vertex>
	#include <morphinstance_vertex>
	#include <morphnormal_vertex>
	#include <skinbase_vertex>
	#include <skinnormal_vertex>
	#include <defaultnormal_vertex>
	#include <begin_vertex>
	#include <morphtarget_vertex>
	#include <skinning_vertex>
	#include <project_vertex>
	#include <logdepthbuf_vertex>
	#include <worldpos_vertex>
	#include <shadowmap_vertex>
	#include <fog_vertex>
}`,IM=`uniform vec3 color;
uniform float opacity;
#include <common>
#include <fog_pars_fragment>
#include <bsdfs>
#include <lights_pars_begin>
#include <logdepthbuf_pars_fragment>
#include <shadowmap_pars_fragment>
#include <shadowmask_pars_fragment>
void main() {
	#include <logdepthbuf_fragment>
	gl_FragColor = vec4( color, opacity * ( 1.0 - getShadowMask() ) );
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
	#include <premultiplied_alpha_fragment>
}`,PM=`uniform float rotation;
uniform vec2 center;
#include <common>
#include <uv_pars_vertex>
#include <fog_pars_vertex>
#include <logdepthbuf_pars_vertex>
#include <clipping_planes_pars_vertex>
void main() {
	#include <uv_vertex>
	vec4 mvPosition = modelViewMatrix[ 3 ];
	vec2 scale = vec2( length( modelMatrix[ 0 ].xyz ), length( modelMatrix[ 1 ].xyz ) );
	#ifndef USE_SIZEATTENUATION
		bool isPerspective = isPerspectiveMatrix( projectionMatrix );
		if ( isPerspective ) scale *= - mvPosition.z;
	#endif
	vec2 alignedPosition = ( position.xy - ( center - vec2( 0.5 ) ) ) * scale;
	vec2 rotatedPosition;
	rotatedPosition.x = cos( rotation ) * alignedPosition.x - sin( rotation ) * alignedPosition.y;
	rotatedPosition.y = sin( rotation ) * alignedPosition.x + cos( rotation ) * alignedPosition.y;
	mvPosition.xy += rotatedPosition;
	gl_Position = projectionMatrix * mvPosition;
	#include <logdepthbuf_vertex>
	#include <clipping_planes_vertex>
	#include <fog_vertex>
}`,LM=`uniform vec3 diffuse;
uniform float opacity;
#include <common>
#include <uv_pars_fragment>
#include <map_pars_fragment>
#include <alphamap_pars_fragment>
#include <alphatest_pars_fragment>
#include <alphahash_pars_fragment>
#include <fog_pars_fragment>
#include <logdepthbuf_pars_fragment>
#include <clipping_planes_pars_fragment>
void main() {
	vec4 diffuseColor = vec4( diffuse, opacity );
	#include <clipping_planes_fragment>
	vec3 outgoingLight = vec3( 0.0 );
	#include <logdepthbuf_fragment>
	#include <map_fragment>
	#include <alphamap_fragment>
	#include <alphatest_fragment>
	#include <alphahash_fragment>
	outgoingLight = diffuseColor.rgb;
	#include <opaque_fragment>
	#include <tonemapping_fragment>
	#include <colorspace_fragment>
	#include <fog_fragment>
}`,_t={alphahash_fragment:eS,alphahash_pars_fragment:tS,alphamap_fragment:nS,alphamap_pars_fragment:iS,alphatest_fragment:sS,alphatest_pars_fragment:rS,aomap_fragment:oS,aomap_pars_fragment:aS,batching_pars_vertex:lS,batching_vertex:cS,begin_vertex:hS,beginnormal_vertex:uS,bsdfs:fS,iridescence_fragment:dS,bumpmap_pars_fragment:pS,clipping_planes_fragment:mS,clipping_planes_pars_fragment:gS,clipping_planes_pars_vertex:_S,clipping_planes_vertex:xS,color_fragment:yS,color_pars_fragment:vS,color_pars_vertex:SS,color_vertex:bS,common:MS,defaultnormal_vertex:wS,displacementmap_pars_vertex:ES,displacementmap_vertex:TS,emissivemap_fragment:AS,emissivemap_pars_fragment:RS,colorspace_fragment:CS,colorspace_pars_fragment:IS,envmap_fragment:PS,envmap_common_pars_fragment:LS,envmap_pars_fragment:NS,envmap_pars_vertex:DS,envmap_physical_pars_fragment:XS,envmap_vertex:US,fog_vertex:OS,fog_pars_vertex:FS,fog_fragment:BS,fog_pars_fragment:kS,gradientmap_pars_fragment:zS,lightmap_pars_fragment:GS,lights_lambert_fragment:HS,lights_lambert_pars_fragment:VS,lights_pars_begin:WS,lights_toon_fragment:qS,lights_toon_pars_fragment:YS,lights_phong_fragment:$S,lights_phong_pars_fragment:ZS,lights_physical_fragment:KS,lights_physical_pars_fragment:JS,lights_fragment_begin:jS,lights_fragment_maps:QS,lights_fragment_end:eb,lightprobes_pars_fragment:tb,logdepthbuf_fragment:nb,logdepthbuf_pars_fragment:ib,logdepthbuf_pars_vertex:sb,logdepthbuf_vertex:rb,map_fragment:ob,map_pars_fragment:ab,map_particle_fragment:lb,map_particle_pars_fragment:cb,metalnessmap_fragment:hb,metalnessmap_pars_fragment:ub,morphinstance_vertex:fb,morphcolor_vertex:db,morphnormal_vertex:pb,morphtarget_pars_vertex:mb,morphtarget_vertex:gb,normal_fragment_begin:_b,normal_fragment_maps:xb,normal_pars_fragment:yb,normal_pars_vertex:vb,normal_vertex:Sb,normalmap_pars_fragment:bb,clearcoat_normal_fragment_begin:Mb,clearcoat_normal_fragment_maps:wb,clearcoat_pars_fragment:Eb,iridescence_pars_fragment:Tb,opaque_fragment:Ab,packing:Rb,premultiplied_alpha_fragment:Cb,project_vertex:Ib,dithering_fragment:Pb,dithering_pars_fragment:Lb,roughnessmap_fragment:Nb,roughnessmap_pars_fragment:Db,shadowmap_pars_fragment:Ub,shadowmap_pars_vertex:Ob,shadowmap_vertex:Fb,shadowmask_pars_fragment:Bb,skinbase_vertex:kb,skinning_pars_vertex:zb,skinning_vertex:Gb,skinnormal_vertex:Hb,specularmap_fragment:Vb,specularmap_pars_fragment:Wb,tonemapping_fragment:Xb,tonemapping_pars_fragment:qb,transmission_fragment:Yb,transmission_pars_fragment:$b,uv_pars_fragment:Zb,uv_pars_vertex:Kb,uv_vertex:Jb,worldpos_vertex:jb,background_vert:Qb,background_frag:eM,backgroundCube_vert:tM,backgroundCube_frag:nM,cube_vert:iM,cube_frag:sM,depth_vert:rM,depth_frag:oM,distance_vert:aM,distance_frag:lM,equirect_vert:cM,equirect_frag:hM,linedashed_vert:uM,linedashed_frag:fM,meshbasic_vert:dM,meshbasic_frag:pM,meshlambert_vert:mM,meshlambert_frag:gM,meshmatcap_vert:_M,meshmatcap_frag:xM,meshnormal_vert:yM,meshnormal_frag:vM,meshphong_vert:SM,meshphong_frag:bM,meshphysical_vert:MM,meshphysical_frag:wM,meshtoon_vert:EM,meshtoon_frag:TM,points_vert:AM,points_frag:RM,shadow_vert:CM,shadow_frag:IM,sprite_vert:PM,sprite_frag:LM},Ue={common:{diffuse:{value:new gt(16777215)},opacity:{value:1},map:{value:null},mapTransform:{value:new ot},alphaMap:{value:null},alphaMapTransform:{value:new ot},alphaTest:{value:0}},specularmap:{specularMap:{value:null},specularMapTransform:{value:new ot}},envmap:{envMap:{value:null},envMapRotation:{value:new ot},reflectivity:{value:1},ior:{value:1.5},refractionRatio:{value:.98},dfgLUT:{value:null}},aomap:{aoMap:{value:null},aoMapIntensity:{value:1},aoMapTransform:{value:new ot}},lightmap:{lightMap:{value:null},lightMapIntensity:{value:1},lightMapTransform:{value:new ot}},bumpmap:{bumpMap:{value:null},bumpMapTransform:{value:new ot},bumpScale:{value:1}},normalmap:{normalMap:{value:null},normalMapTransform:{value:new ot},normalScale:{value:new ut(1,1)}},displacementmap:{displacementMap:{value:null},displacementMapTransform:{value:new ot},displacementScale:{value:1},displacementBias:{value:0}},emissivemap:{emissiveMap:{value:null},emissiveMapTransform:{value:new ot}},metalnessmap:{metalnessMap:{value:null},metalnessMapTransform:{value:new ot}},roughnessmap:{roughnessMap:{value:null},roughnessMapTransform:{value:new ot}},gradientmap:{gradientMap:{value:null}},fog:{fogDensity:{value:25e-5},fogNear:{value:1},fogFar:{value:2e3},fogColor:{value:new gt(16777215)}},lights:{ambientLightColor:{value:[]},lightProbe:{value:[]},sunLights:{value:[],properties:{direction:{},color:{}}},sunLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},sunShadowMatrix:{value:[]},sunShadowCascade:{value:[]},directionalLights:{value:[],properties:{direction:{},color:{}}},directionalLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},directionalShadowMatrix:{value:[]},spotLights:{value:[],properties:{color:{},position:{},direction:{},distance:{},coneCos:{},penumbraCos:{},decay:{}}},spotLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{}}},spotLightMap:{value:[]},spotLightMatrix:{value:[]},pointLights:{value:[],properties:{color:{},position:{},decay:{},distance:{}}},pointLightShadows:{value:[],properties:{shadowIntensity:1,shadowBias:{},shadowNormalBias:{},shadowRadius:{},shadowMapSize:{},shadowCameraNear:{},shadowCameraFar:{}}},pointShadowMatrix:{value:[]},hemisphereLights:{value:[],properties:{direction:{},skyColor:{},groundColor:{}}},rectAreaLights:{value:[],properties:{color:{},position:{},width:{},height:{}}},ltc_1:{value:null},ltc_2:{value:null},probesSH:{value:[]},probesMin:{value:[]},probesMax:{value:[]},probesResolution:{value:[]}},points:{diffuse:{value:new gt(16777215)},opacity:{value:1},size:{value:1},scale:{value:1},map:{value:null},alphaMap:{value:null},alphaMapTransform:{value:new ot},alphaTest:{value:0},uvTransform:{value:new ot}},sprite:{diffuse:{value:new gt(16777215)},opacity:{value:1},center:{value:new ut(.5,.5)},rotation:{value:0},map:{value:null},mapTransform:{value:new ot},alphaMap:{value:null},alphaMapTransform:{value:new ot},alphaTest:{value:0}}},is={basic:{uniforms:kn([Ue.common,Ue.specularmap,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.fog]),vertexShader:_t.meshbasic_vert,fragmentShader:_t.meshbasic_frag},lambert:{uniforms:kn([Ue.common,Ue.specularmap,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.fog,Ue.lights,{emissive:{value:new gt(0)},envMapIntensity:{value:1}}]),vertexShader:_t.meshlambert_vert,fragmentShader:_t.meshlambert_frag},phong:{uniforms:kn([Ue.common,Ue.specularmap,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.fog,Ue.lights,{emissive:{value:new gt(0)},specular:{value:new gt(1118481)},shininess:{value:30},envMapIntensity:{value:1}}]),vertexShader:_t.meshphong_vert,fragmentShader:_t.meshphong_frag},standard:{uniforms:kn([Ue.common,Ue.envmap,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.roughnessmap,Ue.metalnessmap,Ue.fog,Ue.lights,{emissive:{value:new gt(0)},roughness:{value:1},metalness:{value:0},envMapIntensity:{value:1}}]),vertexShader:_t.meshphysical_vert,fragmentShader:_t.meshphysical_frag},toon:{uniforms:kn([Ue.common,Ue.aomap,Ue.lightmap,Ue.emissivemap,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.gradientmap,Ue.fog,Ue.lights,{emissive:{value:new gt(0)}}]),vertexShader:_t.meshtoon_vert,fragmentShader:_t.meshtoon_frag},matcap:{uniforms:kn([Ue.common,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,Ue.fog,{matcap:{value:null}}]),vertexShader:_t.meshmatcap_vert,fragmentShader:_t.meshmatcap_frag},points:{uniforms:kn([Ue.points,Ue.fog]),vertexShader:_t.points_vert,fragmentShader:_t.points_frag},dashed:{uniforms:kn([Ue.common,Ue.fog,{scale:{value:1},dashSize:{value:1},totalSize:{value:2}}]),vertexShader:_t.linedashed_vert,fragmentShader:_t.linedashed_frag},depth:{uniforms:kn([Ue.common,Ue.displacementmap]),vertexShader:_t.depth_vert,fragmentShader:_t.depth_frag},normal:{uniforms:kn([Ue.common,Ue.bumpmap,Ue.normalmap,Ue.displacementmap,{opacity:{value:1}}]),vertexShader:_t.meshnormal_vert,fragmentShader:_t.meshnormal_frag},sprite:{uniforms:kn([Ue.sprite,Ue.fog]),vertexShader:_t.sprite_vert,fragmentShader:_t.sprite_frag},background:{uniforms:{uvTransform:{value:new ot},t2D:{value:null},backgroundIntensity:{value:1}},vertexShader:_t.background_vert,fragmentShader:_t.background_frag},backgroundCube:{uniforms:{envMap:{value:null},backgroundBlurriness:{value:0},backgroundIntensity:{value:1},backgroundRotation:{value:new ot}},vertexShader:_t.backgroundCube_vert,fragmentShader:_t.backgroundCube_frag},cube:{uniforms:{tCube:{value:null},tFlip:{value:-1},opacity:{value:1}},vertexShader:_t.cube_vert,fragmentShader:_t.cube_frag},equirect:{uniforms:{tEquirect:{value:null}},vertexShader:_t.equirect_vert,fragmentShader:_t.equirect_frag},distance:{uniforms:kn([Ue.common,Ue.displacementmap,{referencePosition:{value:new K},nearDistance:{value:1},farDistance:{value:1e3}}]),vertexShader:_t.distance_vert,fragmentShader:_t.distance_frag},shadow:{uniforms:kn([Ue.lights,Ue.fog,{color:{value:new gt(0)},opacity:{value:1}}]),vertexShader:_t.shadow_vert,fragmentShader:_t.shadow_frag}};is.physical={uniforms:kn([is.standard.uniforms,{clearcoat:{value:0},clearcoatMap:{value:null},clearcoatMapTransform:{value:new ot},clearcoatNormalMap:{value:null},clearcoatNormalMapTransform:{value:new ot},clearcoatNormalScale:{value:new ut(1,1)},clearcoatRoughness:{value:0},clearcoatRoughnessMap:{value:null},clearcoatRoughnessMapTransform:{value:new ot},diffuseRoughness:{value:0},diffuseRoughnessMap:{value:null},diffuseRoughnessMapTransform:{value:new ot},dispersion:{value:0},retroreflectivity:{value:0},iridescence:{value:0},iridescenceMap:{value:null},iridescenceMapTransform:{value:new ot},iridescenceIOR:{value:1.3},iridescenceThicknessMinimum:{value:100},iridescenceThicknessMaximum:{value:400},iridescenceThicknessMap:{value:null},iridescenceThicknessMapTransform:{value:new ot},sheen:{value:0},sheenColor:{value:new gt(0)},sheenColorMap:{value:null},sheenColorMapTransform:{value:new ot},sheenRoughness:{value:1},sheenRoughnessMap:{value:null},sheenRoughnessMapTransform:{value:new ot},transmission:{value:0},transmissionMap:{value:null},transmissionMapTransform:{value:new ot},transmissionSamplerSize:{value:new ut},transmissionSamplerMap:{value:null},thickness:{value:0},thicknessMap:{value:null},thicknessMapTransform:{value:new ot},attenuationDistance:{value:0},attenuationColor:{value:new gt(0)},specularColor:{value:new gt(1,1,1)},specularColorMap:{value:null},specularColorMapTransform:{value:new ot},specularIntensity:{value:1},specularIntensityMap:{value:null},specularIntensityMapTransform:{value:new ot},anisotropyVector:{value:new ut},anisotropyMap:{value:null},anisotropyMapTransform:{value:new ot}}]),vertexShader:_t.meshphysical_vert,fragmentShader:_t.meshphysical_frag};var Dh={r:0,b:0,g:0},NM=new en,Q0=new ot;Q0.set(-1,0,0,0,1,0,0,0,1);function DM(n,e,t,i,s,r){let o=new gt(0),a=s===!0?0:1,l,c,h=null,f=0,u=null;function p(y){let A=y.isScene===!0?y.background:null;if(A&&A.isTexture){let b=y.backgroundBlurriness>0;A=e.get(A,b)}return A}function g(y){let A=!1,b=p(y);b===null?d(o,a):b&&b.isColor&&(d(b,1),A=!0);let C=n.xr.getEnvironmentBlendMode();C==="additive"?t.buffers.color.setClear(0,0,0,1,r):C==="alpha-blend"&&t.buffers.color.setClear(0,0,0,0,r),(n.autoClear||A)&&(t.buffers.depth.setTest(!0),t.buffers.depth.setMask(!0),t.buffers.color.setMask(!0),n.clear(n.autoClearColor,n.autoClearDepth,n.autoClearStencil))}function S(y,A){let b=p(A);b&&b.isCubeTexture?(c===void 0&&(c=new ji(new Co(1,1,1),new Qi({name:"BackgroundCubeMaterial",uniforms:Lr(is.backgroundCube.uniforms),vertexShader:is.backgroundCube.vertexShader,fragmentShader:is.backgroundCube.fragmentShader,side:$n,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),c.geometry.deleteAttribute("normal"),c.geometry.deleteAttribute("uv"),c.onBeforeRender=function(C,E,x){this.matrixWorld.copyPosition(x.matrixWorld)},Object.defineProperty(c.material,"envMap",{get:function(){return this.uniforms.envMap.value}}),i.update(c)),c.material.uniforms.envMap.value=b,c.material.uniforms.backgroundBlurriness.value=A.backgroundBlurriness,c.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,c.material.uniforms.backgroundRotation.value.setFromMatrix4(NM.makeRotationFromEuler(A.backgroundRotation)).transpose(),b.isRenderTargetTexture===!1&&c.material.uniforms.backgroundRotation.value.premultiply(Q0),c.material.toneMapped=At.getTransfer(b.colorSpace)!==Ft,(h!==b||f!==b.version||u!==n.toneMapping)&&(c.material.needsUpdate=!0,h=b,f=b.version,u=n.toneMapping),c.layers.enableAll(),y.unshift(c,c.geometry,c.material,0,0,null)):b&&b.isTexture&&(l===void 0&&(l=new ji(new Oa(2,2),new Qi({name:"BackgroundMaterial",uniforms:Lr(is.background.uniforms),vertexShader:is.background.vertexShader,fragmentShader:is.background.fragmentShader,side:rr,depthTest:!1,depthWrite:!1,fog:!1,allowOverride:!1})),l.geometry.deleteAttribute("normal"),Object.defineProperty(l.material,"map",{get:function(){return this.uniforms.t2D.value}}),i.update(l)),l.material.uniforms.t2D.value=b,l.material.uniforms.backgroundIntensity.value=A.backgroundIntensity,l.material.toneMapped=At.getTransfer(b.colorSpace)!==Ft,b.matrixAutoUpdate===!0&&b.updateMatrix(),l.material.uniforms.uvTransform.value.copy(b.matrix),(h!==b||f!==b.version||u!==n.toneMapping)&&(l.material.needsUpdate=!0,h=b,f=b.version,u=n.toneMapping),l.layers.enableAll(),y.unshift(l,l.geometry,l.material,0,0,null))}function d(y,A){y.getRGB(Dh,ad(n)),t.buffers.color.setClear(Dh.r,Dh.g,Dh.b,A,r)}function m(){c!==void 0&&(c.geometry.dispose(),c.material.dispose(),c=void 0),l!==void 0&&(l.geometry.dispose(),l.material.dispose(),l=void 0)}return{getClearColor:function(){return o},setClearColor:function(y,A=1){o.set(y),a=A,d(o,a)},getClearAlpha:function(){return a},setClearAlpha:function(y){a=y,d(o,a)},render:g,addToRenderList:S,dispose:m}}function UM(n,e){let t=n.getParameter(n.MAX_VERTEX_ATTRIBS),i={},s=u(null),r=s,o=!1;function a(P,B,z,L,H){let W=!1,D=f(P,L,z,B);r!==D&&(r=D,c(r.object)),W=p(P,L,z,H),W&&g(P,L,z,H),H!==null&&e.update(H,n.ELEMENT_ARRAY_BUFFER),(W||o)&&(o=!1,b(P,B,z,L),H!==null&&n.bindBuffer(n.ELEMENT_ARRAY_BUFFER,e.get(H).buffer))}function l(){return n.createVertexArray()}function c(P){return n.bindVertexArray(P)}function h(P){return n.deleteVertexArray(P)}function f(P,B,z,L){let H=L.wireframe===!0,W=i[B.id];W===void 0&&(W={},i[B.id]=W);let D=P.isInstancedMesh===!0?P.id:0,te=W[D];te===void 0&&(te={},W[D]=te);let X=te[z.id];X===void 0&&(X={},te[z.id]=X);let q=X[H];return q===void 0&&(q=u(l()),X[H]=q),q}function u(P){let B=[],z=[],L=[];for(let H=0;H<t;H++)B[H]=0,z[H]=0,L[H]=0;return{geometry:null,program:null,wireframe:!1,newAttributes:B,enabledAttributes:z,attributeDivisors:L,object:P,attributes:{},index:null}}function p(P,B,z,L){let H=r.attributes,W=B.attributes,D=0,te=z.getAttributes();for(let X in te)if(te[X].location>=0){let j=H[X],ae=W[X];if(ae===void 0&&(X==="instanceMatrix"&&P.instanceMatrix&&(ae=P.instanceMatrix),X==="instanceColor"&&P.instanceColor&&(ae=P.instanceColor)),j===void 0||j.attribute!==ae||ae&&j.data!==ae.data)return!0;D++}return r.attributesNum!==D||r.index!==L}function g(P,B,z,L){let H={},W=B.attributes,D=0,te=z.getAttributes();for(let X in te)if(te[X].location>=0){let j=W[X];j===void 0&&(X==="instanceMatrix"&&P.instanceMatrix&&(j=P.instanceMatrix),X==="instanceColor"&&P.instanceColor&&(j=P.instanceColor));let ae={};ae.attribute=j,j&&j.data&&(ae.data=j.data),H[X]=ae,D++}r.attributes=H,r.attributesNum=D,r.index=L}function S(){let P=r.newAttributes;for(let B=0,z=P.length;B<z;B++)P[B]=0}function d(P){m(P,0)}function m(P,B){let z=r.newAttributes,L=r.enabledAttributes,H=r.attributeDivisors;z[P]=1,L[P]===0&&(n.enableVertexAttribArray(P),L[P]=1),H[P]!==B&&(n.vertexAttribDivisor(P,B),H[P]=B)}function y(){let P=r.newAttributes,B=r.enabledAttributes;for(let z=0,L=B.length;z<L;z++)B[z]!==P[z]&&(n.disableVertexAttribArray(z),B[z]=0)}function A(P,B,z,L,H,W,D){D===!0?n.vertexAttribIPointer(P,B,z,H,W):n.vertexAttribPointer(P,B,z,L,H,W)}function b(P,B,z,L){S();let H=L.attributes,W=z.getAttributes(),D=B.defaultAttributeValues;for(let te in W){let X=W[te];if(X.location>=0){let q=H[te];if(q===void 0&&(te==="instanceMatrix"&&P.instanceMatrix&&(q=P.instanceMatrix),te==="instanceColor"&&P.instanceColor&&(q=P.instanceColor)),q!==void 0){let j=q.normalized,ae=q.itemSize,ce=e.get(q);if(ce===void 0)continue;let ee=ce.buffer,pe=ce.type,fe=ce.bytesPerElement,Me=pe===n.INT||pe===n.UNSIGNED_INT||q.gpuType===jc;if(q.isInterleavedBufferAttribute){let ye=q.data,qe=ye.isInterleavedBuffer===!0?ye.stride:ye.itemSize,it=q.offset;if(ye.isInstancedInterleavedBuffer||ye.isInstancedBufferAttribute){for(let We=0;We<X.locationSize;We++)m(X.location+We,ye.meshPerAttribute);P.isInstancedMesh!==!0&&L._maxInstanceCount===void 0&&(L._maxInstanceCount=ye.meshPerAttribute*ye.count)}else for(let We=0;We<X.locationSize;We++)d(X.location+We);n.bindBuffer(n.ARRAY_BUFFER,ee);for(let We=0;We<X.locationSize;We++)A(X.location+We,ae/X.locationSize,pe,j,qe*fe,(it+ae/X.locationSize*We)*fe,Me)}else{if(q.isInstancedBufferAttribute){for(let ye=0;ye<X.locationSize;ye++)m(X.location+ye,q.meshPerAttribute);P.isInstancedMesh!==!0&&L._maxInstanceCount===void 0&&(L._maxInstanceCount=q.meshPerAttribute*q.count)}else for(let ye=0;ye<X.locationSize;ye++)d(X.location+ye);n.bindBuffer(n.ARRAY_BUFFER,ee);for(let ye=0;ye<X.locationSize;ye++)A(X.location+ye,ae/X.locationSize,pe,j,ae*fe,ae/X.locationSize*ye*fe,Me)}}else if(D!==void 0){let j=D[te];if(j!==void 0)switch(j.length){case 2:n.vertexAttrib2fv(X.location,j);break;case 3:n.vertexAttrib3fv(X.location,j);break;case 4:n.vertexAttrib4fv(X.location,j);break;default:n.vertexAttrib1fv(X.location,j)}}}}y()}function C(){k();for(let P in i){let B=i[P];for(let z in B){let L=B[z];for(let H in L){let W=L[H];for(let D in W)h(W[D].object),delete W[D];delete L[H]}}delete i[P]}}function E(P){if(i[P.id]===void 0)return;let B=i[P.id];for(let z in B){let L=B[z];for(let H in L){let W=L[H];for(let D in W)h(W[D].object),delete W[D];delete L[H]}}delete i[P.id]}function x(P){for(let B in i){let z=i[B];for(let L in z){let H=z[L];if(H[P.id]===void 0)continue;let W=H[P.id];for(let D in W)h(W[D].object),delete W[D];delete H[P.id]}}}function T(P){for(let B in i){let z=i[B],L=P.isInstancedMesh===!0?P.id:0,H=z[L];if(H!==void 0){for(let W in H){let D=H[W];for(let te in D)h(D[te].object),delete D[te];delete H[W]}delete z[L],Object.keys(z).length===0&&delete i[B]}}}function k(){U(),o=!0,r!==s&&(r=s,c(r.object))}function U(){s.geometry=null,s.program=null,s.wireframe=!1}return{setup:a,reset:k,resetDefaultState:U,dispose:C,releaseStatesOfGeometry:E,releaseStatesOfObject:T,releaseStatesOfProgram:x,initAttributes:S,enableAttribute:d,disableUnusedAttributes:y}}function OM(n,e,t){let i;function s(l){i=l}function r(l,c){n.drawArrays(i,l,c),t.update(c,i,1)}function o(l,c,h){h!==0&&(n.drawArraysInstanced(i,l,c,h),t.update(c,i,h))}function a(l,c,h){if(h===0)return;e.get("WEBGL_multi_draw").multiDrawArraysWEBGL(i,l,0,c,0,h);let u=0;for(let p=0;p<h;p++)u+=c[p];t.update(u,i,1)}this.setMode=s,this.render=r,this.renderInstances=o,this.renderMultiDraw=a}function FM(n,e,t,i){let s;function r(){if(s!==void 0)return s;if(e.has("EXT_texture_filter_anisotropic")===!0){let x=e.get("EXT_texture_filter_anisotropic");s=n.getParameter(x.MAX_TEXTURE_MAX_ANISOTROPY_EXT)}else s=0;return s}function o(x){return!(x!==Bi&&i.convert(x)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_FORMAT))}function a(x){let T=x===Fi&&(e.has("EXT_color_buffer_half_float")||e.has("EXT_color_buffer_float"));return!(x!==gi&&x!==Oi&&!T&&i.convert(x)!==n.getParameter(n.IMPLEMENTATION_COLOR_READ_TYPE))}function l(x){if(x==="highp"){if(n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.HIGH_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.HIGH_FLOAT).precision>0)return"highp";x="mediump"}return x==="mediump"&&n.getShaderPrecisionFormat(n.VERTEX_SHADER,n.MEDIUM_FLOAT).precision>0&&n.getShaderPrecisionFormat(n.FRAGMENT_SHADER,n.MEDIUM_FLOAT).precision>0?"mediump":"lowp"}let c=t.precision!==void 0?t.precision:"highp",h=l(c);h!==c&&(Je("WebGLRenderer:",c,"not supported, using",h,"instead."),c=h);let f=t.reversedDepthBuffer===!0&&e.has("EXT_clip_control"),u=t.logarithmicDepthBuffer===!0&&f===!1;t.reversedDepthBuffer===!0&&f===!1&&Je("WebGLRenderer: Unable to use reversed depth buffer due to missing EXT_clip_control extension. Fallback to default depth buffer."),t.logarithmicDepthBuffer===!0&&f===!0&&Je("WebGLRenderer: Logarithmic depth buffer is ignored when reversed depth buffer is enabled.");let p=n.getParameter(n.MAX_TEXTURE_IMAGE_UNITS),g=n.getParameter(n.MAX_VERTEX_TEXTURE_IMAGE_UNITS),S=n.getParameter(n.MAX_TEXTURE_SIZE),d=n.getParameter(n.MAX_CUBE_MAP_TEXTURE_SIZE),m=n.getParameter(n.MAX_VERTEX_ATTRIBS),y=n.getParameter(n.MAX_VERTEX_UNIFORM_VECTORS),A=n.getParameter(n.MAX_VARYING_VECTORS),b=n.getParameter(n.MAX_FRAGMENT_UNIFORM_VECTORS),C=n.getParameter(n.MAX_SAMPLES),E=n.getParameter(n.SAMPLES);return{isWebGL2:!0,getMaxAnisotropy:r,getMaxPrecision:l,textureFormatReadable:o,textureTypeReadable:a,precision:c,logarithmicDepthBuffer:u,reversedDepthBuffer:f,maxTextures:p,maxVertexTextures:g,maxTextureSize:S,maxCubemapSize:d,maxAttributes:m,maxVertexUniforms:y,maxVaryings:A,maxFragmentUniforms:b,maxSamples:C,samples:E}}function BM(n){let e=this,t=null,i=0,s=!1,r=!1,o=new ui,a=new ot,l={value:null,needsUpdate:!1};this.uniform=l,this.numPlanes=0,this.numIntersection=0,this.init=function(f,u){let p=f.length!==0||u||i!==0||s;return s=u,i=f.length,p},this.beginShadows=function(){r=!0,h(null)},this.endShadows=function(){r=!1},this.setGlobalState=function(f,u){t=h(f,u,0)},this.setState=function(f,u,p){let g=f.clippingPlanes,S=f.clipIntersection,d=f.clipShadows,m=n.get(f);if(!s||g===null||g.length===0||r&&!d)r?h(null):c();else{let y=r?0:i,A=y*4,b=m.clippingState||null;l.value=b,b=h(g,u,A,p);for(let C=0;C!==A;++C)b[C]=t[C];m.clippingState=b,this.numIntersection=S?this.numPlanes:0,this.numPlanes+=y}};function c(){l.value!==t&&(l.value=t,l.needsUpdate=i>0),e.numPlanes=i,e.numIntersection=0}function h(f,u,p,g){let S=f!==null?f.length:0,d=null;if(S!==0){if(d=l.value,g!==!0||d===null){let m=p+S*4,y=u.matrixWorldInverse;a.getNormalMatrix(y),(d===null||d.length<m)&&(d=new Float32Array(m));for(let A=0,b=p;A!==S;++A,b+=4)o.copy(f[A]).applyMatrix4(y,a),o.normal.toArray(d,b),d[b+3]=o.constant}l.value=d,l.needsUpdate=!0}return e.numPlanes=S,e.numIntersection=0,d}}var ja=class extends pi{constructor(e=1,t={}){super(e,e,t),this.isWebGLCubeRenderTarget=!0;let i={width:e,height:e,depth:1},s=[i,i,i,i,i,i];this.texture=new Na(s),this._setTextureOptions(t),this.texture.isRenderTargetTexture=!0}fromEquirectangularTexture(e,t){this.texture.type=t.type,this.texture.colorSpace=t.colorSpace,this.texture.generateMipmaps=t.generateMipmaps,this.texture.minFilter=t.minFilter,this.texture.magFilter=t.magFilter;let i={uniforms:{tEquirect:{value:null}},vertexShader:`

				varying vec3 vWorldDirection;

				vec3 transformDirection( in vec3 dir, in mat4 matrix ) {

					return normalize( ( matrix * vec4( dir, 0.0 ) ).xyz );

				}

				void main() {

					vWorldDirection = transformDirection( position, modelMatrix );

					#include <begin_vertex>
					#include <project_vertex>

				}
			`,fragmentShader:`

				uniform sampler2D tEquirect;

				varying vec3 vWorldDirection;

				#include <common>

				void main() {

					vec3 direction = normalize( vWorldDirection );

					vec2 sampleUV = equirectUv( direction );

					gl_FragColor = texture2D( tEquirect, sampleUV );

				}
			`},s=new Co(5,5,5),r=new Qi({name:"CubemapFromEquirect",uniforms:Lr(i.uniforms),vertexShader:i.vertexShader,fragmentShader:i.fragmentShader,side:$n,blending:Rr});r.uniforms.tEquirect.value=t;let o=new ji(s,r),a=t.minFilter;return t.minFilter===ws&&(t.minFilter=Yn),new Io(1,10,this).update(e,o),t.minFilter=a,o.geometry.dispose(),o.material.dispose(),this}clear(e,t=!0,i=!0,s=!0){let r=e.getRenderTarget();for(let o=0;o<6;o++)e.setRenderTarget(this,o),e.clear(t,i,s);e.setRenderTarget(r)}},P0=256,kM=3,zM=20,e_=256,t_=16,GM=3,HM=new K,VM=new gt,Oh=class n{constructor(e){this._renderer=e,this._cubeSize=0,this._sourceTarget=null,this._cubeCamera=new Io(1,10,null),this._boxMesh=new ji(new Co(5,5,5),null),this._cubemapMaterial=null,this._equirectMaterial=null,this._blurMaterial=null,this._ggxMaterial=null,this._integrationMaterial=null}fromScene(e,t=0,i=.1,s=100,r={}){let{size:o=256,position:a=HM}=r,l=this._renderer;this._setSize(o);let c=this._allocateTarget(),h=this._getSourceTarget(!0);t>0&&(h.texture.mipmapsAutoUpdate=!1);let f=l.autoClear,u=l.autoClearColor,p=l.autoClearDepth,g=l.autoClearStencil,S=e.background;l.autoClear=!0,l.autoClearColor=!0,l.autoClearDepth=!0,l.autoClearStencil=!0,S===null&&(e.background=l.getClearColor(VM));let d=new Io(i,s,h);return d.position.copy(a),d.update(l,e),l.autoClear=f,l.autoClearColor=u,l.autoClearDepth=p,l.autoClearStencil=g,e.background=S,t>0&&(h.texture.mipmapsAutoUpdate=!0,this._blur(c,t)),this._applyPMREM(c),c}fromEquirectangular(e,t=null){return this._fromTexture(e,t)}fromCubemap(e,t=null){return this._fromTexture(e,t)}compileCubemapShader(){this._cubemapMaterial===null&&(this._cubemapMaterial=D0(),this._compileMaterial(this._cubemapMaterial))}compileEquirectangularShader(){this._equirectMaterial===null&&(this._equirectMaterial=N0(),this._compileMaterial(this._equirectMaterial))}dispose(){this._sourceTarget!==null&&this._sourceTarget.dispose(),this._cubemapMaterial!==null&&this._cubemapMaterial.dispose(),this._equirectMaterial!==null&&this._equirectMaterial.dispose(),this._blurMaterial!==null&&this._blurMaterial.dispose(),this._ggxMaterial!==null&&this._ggxMaterial.dispose(),this._integrationMaterial!==null&&this._integrationMaterial.dispose(),this._boxMesh.geometry.dispose()}static lodToRoughness(e,t){return t>0?1-Math.sqrt(1-e/t):0}_setSize(e){this._cubeSize=Math.max(P0,sd(e))}_fromTexture(e,t){e.mapping===Ir||e.mapping===Do?this._setSize(e.image.length===0?P0:e.image[0].width||e.image[0].image.width):this._setSize(e.image.width/4);let i=t||this._allocateTarget();return this._textureToCubemap(e),this._applyPMREM(i),i}_allocateTarget(){let e=this._cubeSize,t=L0(e,!1,!1),i=Math.log2(e)-kM;for(let s=0;s<=i;s++)t.texture.mipmaps.push({width:e>>s,height:e>>s});return t.texture.name="PMREM",t.texture.isPMREMTexture=!0,t}_getSourceTarget(e=!1){let t=this._cubeSize,i=this._sourceTarget;return(i===null||i.width!==t||e&&i.depthBuffer===!1)&&(i!==null&&i.dispose(),this._sourceTarget=L0(t,!0,e)),this._sourceTarget}_compileMaterial(e){this._boxMesh.material=e,this._renderer.compile(this._boxMesh,this._cubeCamera.children[0])}_renderCube(e,t,i){let s=this._boxMesh,r=this._cubeCamera;s.material=i,r.renderTarget=e,r.activeMipmapLevel=t;let o=e.width>>t;e.viewport.set(0,0,o,o),r.update(this._renderer,s),e.viewport.set(0,0,e.width,e.height)}_textureToCubemap(e){let t;e.mapping===Ir||e.mapping===Do?(this._cubemapMaterial===null&&(this._cubemapMaterial=D0()),t=this._cubemapMaterial,t.uniforms.flipEnvMap.value=e.isRenderTargetTexture===!1?-1:1):(this._equirectMaterial===null&&(this._equirectMaterial=N0()),t=this._equirectMaterial),t.uniforms.envMap.value=e,this._renderCube(this._getSourceTarget(),0,t)}_applyPMREM(e){this._ggxMaterial===null&&(this._ggxMaterial=WM(),this._integrationMaterial=XM());let t=this._cubeSize,i=e.texture.mipmaps.length-1,s=this._ggxMaterial.uniforms;s.envMap.value=this._sourceTarget.texture;let r=this._integrationMaterial.uniforms;r.envMap.value=this._sourceTarget.texture,r.sourceLod.value=Math.log2(t/t_);for(let o=0;o<=i;o++){let a=n.lodToRoughness(o,i);if(o>i-GM)r.roughness.value=a,this._renderCube(e,o,this._integrationMaterial);else{let l=a>0?Math.log2(t)+.5*Math.log2(6/(e_*Math.pow(a,4)))+.5:0;s.roughness.value=a,s.lodBias.value=l,this._renderCube(e,o,this._ggxMaterial)}}}_blur(e,t){this._blurMaterial===null&&(this._blurMaterial=qM());let i=this._blurMaterial,s=i.uniforms,r=this._sourceTarget;s.sigma.value=Math.min(t,Math.PI)/Math.SQRT2,s.envMap.value=r.texture,this._renderCube(e,0,i),s.envMap.value=e.texture,this._renderCube(r,0,i)}};function L0(n,e,t){return new ja(n,{minFilter:ws,generateMipmaps:e,type:Fi,colorSpace:ba,depthBuffer:t})}function Qa(n,e,t){return new Qi({name:n,uniforms:e,vertexShader:_t.cube_vert,fragmentShader:t,side:$n,blending:Rr,depthTest:!1,depthWrite:!1})}function WM(){return Qa("PMREMGGXConvolution",{envMap:{value:null},roughness:{value:0},lodBias:{value:0}},`

		#define GGX_SAMPLES ${e_}u

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float lodBias;

		#include <common>

		// Van der Corput radical inverse
		float radicalInverse_VdC( uint bits ) {

			bits = ( bits << 16u ) | ( bits >> 16u );
			bits = ( ( bits & 0x55555555u ) << 1u ) | ( ( bits & 0xAAAAAAAAu ) >> 1u );
			bits = ( ( bits & 0x33333333u ) << 2u ) | ( ( bits & 0xCCCCCCCCu ) >> 2u );
			bits = ( ( bits & 0x0F0F0F0Fu ) << 4u ) | ( ( bits & 0xF0F0F0F0u ) >> 4u );
			bits = ( ( bits & 0x00FF00FFu ) << 8u ) | ( ( bits & 0xFF00FF00u ) >> 8u );
			return float( bits ) * 2.3283064365386963e-10; // / 0x100000000

		}

		// Hammersley sequence
		vec2 hammersley( uint i, uint N ) {

			return vec2( float( i ) / float( N ), radicalInverse_VdC( i ) );

		}

		void main() {

			vec3 N = normalize( vWorldDirection );

			// For very low roughness, just sample the environment directly
			if ( roughness < 0.001 ) {

				gl_FragColor = vec4( textureLod( envMap, N, 0.0 ).rgb, 1.0 );
				return;

			}

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			// Tangent space basis for VNDF sampling
			vec3 up = abs( N.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, N ) );
			vec3 bitangent = cross( N, tangent );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			for ( uint i = 0u; i < GGX_SAMPLES; i ++ ) {

				vec2 Xi = hammersley( i, GGX_SAMPLES );

				// With V = N, sample the reflected direction directly.
				float invQ = 1.0 / ( 1.0 - Xi.x + alpha2 * Xi.x );
				float NdotL = ( 1.0 - Xi.x - alpha2 * Xi.x ) * invQ;

				if ( NdotL > 0.0 ) {

					float phi = 2.0 * PI * Xi.y;
					float sinTheta = 2.0 * alpha * sqrt( Xi.x * ( 1.0 - Xi.x ) ) * invQ;
					vec3 L = N * NdotL + ( tangent * cos( phi ) + bitangent * sin( phi ) ) * sinTheta;

					// Match the source mip to the sample's solid angle. The terms
					// independent of the sample are precomputed in lodBias.
					float d = alpha2 * invQ;
					float lod = max( log2( d ) + lodBias, 0.0 );

					// Weight by NdotL for the split-sum approximation
					prefilteredColor += textureLod( envMap, L, lod ).rgb * NdotL;
					totalWeight += NdotL;

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function XM(){return Qa("PMREMGGXIntegration",{envMap:{value:null},roughness:{value:0},sourceLod:{value:0},sourceSize:{value:t_}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float roughness;
		uniform float sourceLod;
		uniform int sourceSize;

		void main() {

			vec3 N = normalize( vWorldDirection );

			float alpha = roughness * roughness;
			float alpha2 = alpha * alpha;

			float texelSize = 2.0 / float( sourceSize );

			vec3 prefilteredColor = vec3( 0.0 );
			float totalWeight = 0.0;

			// Pair opposite texels: only the one in N's hemisphere contributes.
			for ( int face = 0; face < 3; face ++ ) {

				for ( int y = 0; y < sourceSize; y ++ ) {

					for ( int x = 0; x < sourceSize; x ++ ) {

						vec2 uv = ( vec2( x, y ) + 0.5 ) * texelSize - 1.0;
						vec3 texelDirection = face == 0 ? vec3( 1.0, uv ) : ( face == 1 ? vec3( uv.x, 1.0, uv.y ) : vec3( uv, 1.0 ) );

						float invDistance = inversesqrt( 1.0 + dot( uv, uv ) );
						float NdotL = dot( N, texelDirection );
						texelDirection *= NdotL < 0.0 ? - 1.0 : 1.0;
						NdotL = abs( NdotL ) * invDistance;

						// With V = N, NdotH squared is ( 1 + NdotL ) / 2. Common factors
						// in the GGX distribution and texel solid angle cancel when normalized.
						float d = 1.0 + alpha2 + ( alpha2 - 1.0 ) * NdotL;
						float weight = NdotL * invDistance * invDistance * invDistance / ( d * d );

						prefilteredColor += textureLod( envMap, texelDirection, sourceLod ).rgb * weight;
						totalWeight += weight;

					}

				}

			}

			gl_FragColor = vec4( prefilteredColor / totalWeight, 1.0 );

		}
	`)}function qM(){return Qa("PMREMSphericalGaussianBlur",{envMap:{value:null},sigma:{value:0}},`

		#define SAMPLES ${zM}
		#define GOLDEN_ANGLE 2.39996322973

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float sigma;

		#include <common>

		void main() {

			vec3 outputDirection = normalize( vWorldDirection );

			vec3 up = abs( outputDirection.z ) < 0.999 ? vec3( 0.0, 0.0, 1.0 ) : vec3( 1.0, 0.0, 0.0 );
			vec3 tangent = normalize( cross( up, outputDirection ) );
			vec3 bitangent = cross( outputDirection, tangent );

			// Truncate the kernel at three standard deviations or at the antipode.
			float thetaMax = min( 3.0 * sigma, PI );
			float truncation = 1.0 - exp( - 0.5 * thetaMax * thetaMax / ( sigma * sigma ) );

			vec3 accumColor = vec3( 0.0 );
			float accumWeight = 0.0;

			for ( int i = 0; i < SAMPLES; i ++ ) {

				// Stratified inverse-CDF sampling of the Gaussian, placed on a golden-angle spiral.
				float stratum = ( float( i ) + 0.5 ) / float( SAMPLES );
				float theta = sigma * sqrt( - 2.0 * log( 1.0 - stratum * truncation ) );
				float phi = float( i ) * GOLDEN_ANGLE;

				vec3 offset = cos( phi ) * tangent + sin( phi ) * bitangent;
				vec3 sampleDirection = cos( theta ) * outputDirection + sin( theta ) * offset;

				// Correct the planar sample density to solid angle.
				float weight = sin( theta ) / theta;

				accumColor += weight * textureLod( envMap, sampleDirection, 0.0 ).rgb;
				accumWeight += weight;

			}

			gl_FragColor = vec4( accumColor / accumWeight, 1.0 );

		}
	`)}function N0(){return Qa("PMREMEquirectangularToCubemap",{envMap:{value:null}},`

		varying vec3 vWorldDirection;

		uniform sampler2D envMap;

		#include <common>

		void main() {

			// Average four subpixel samples to preserve small, bright features.
			vec3 direction = normalize( vWorldDirection );
			vec3 dx = dFdx( direction ) * 0.25;
			vec3 dy = dFdy( direction ) * 0.25;

			vec3 color = textureLod( envMap, equirectUv( normalize( direction - dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx - dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction - dx + dy ) ), 0.0 ).rgb;
			color += textureLod( envMap, equirectUv( normalize( direction + dx + dy ) ), 0.0 ).rgb;
			gl_FragColor = vec4( color * 0.25, 1.0 );

		}
	`)}function D0(){return Qa("PMREMCubemapToCubemap",{envMap:{value:null},flipEnvMap:{value:-1}},`

		varying vec3 vWorldDirection;

		uniform samplerCube envMap;
		uniform float flipEnvMap;

		void main() {

			gl_FragColor = vec4( textureCube( envMap, vec3( flipEnvMap * vWorldDirection.x, vWorldDirection.yz ) ).rgb, 1.0 );

		}
	`)}function YM(n){let e=new WeakMap,t=new WeakMap,i=null;function s(u,p=!1){return u==null?null:p?o(u):r(u)}function r(u){if(u&&u.isTexture){let p=u.mapping;if(p===Zc||p===Kc)if(e.has(u)){let g=e.get(u).texture;return a(g,u.mapping)}else{let g=u.image;if(g&&g.height>0){let S=new ja(g.height);return S.fromEquirectangularTexture(n,u),e.set(u,S),u.addEventListener("dispose",c),a(S.texture,u.mapping)}else return null}}return u}function o(u){if(u&&u.isTexture&&u.isPMREMTexture!==!0){let p=u.mapping,g=p===Zc||p===Kc,S=p===Ir||p===Do;if(g||S){let d=t.get(u),m=d!==void 0?d.texture.pmremVersion:0;if(u.isRenderTargetTexture&&u.pmremVersion!==m)return i===null&&(i=new Oh(n)),d=g?i.fromEquirectangular(u,d):i.fromCubemap(u,d),d.texture.pmremVersion=u.pmremVersion,t.set(u,d),d.texture;if(d!==void 0)return d.texture;{let y=u.image;return g&&y&&y.height>0||S&&y&&l(y)?(i===null&&(i=new Oh(n)),d=g?i.fromEquirectangular(u):i.fromCubemap(u),d.texture.pmremVersion=u.pmremVersion,t.set(u,d),u.addEventListener("dispose",h),d.texture):null}}}return u}function a(u,p){return p===Zc?u.mapping=Ir:p===Kc&&(u.mapping=Do),u}function l(u){let p=0,g=6;for(let S=0;S<g;S++)u[S]!==void 0&&p++;return p===g}function c(u){let p=u.target;p.removeEventListener("dispose",c);let g=e.get(p);g!==void 0&&(e.delete(p),g.dispose())}function h(u){let p=u.target;p.removeEventListener("dispose",h);let g=t.get(p);g!==void 0&&(t.delete(p),g.dispose())}function f(){e=new WeakMap,t=new WeakMap,i!==null&&(i.dispose(),i=null)}return{get:s,dispose:f}}function $M(n){let e={};function t(i){if(e[i]!==void 0)return e[i];let s=n.getExtension(i);return e[i]=s,s}return{has:function(i){return t(i)!==null},init:function(){t("EXT_color_buffer_float"),t("WEBGL_clip_cull_distance"),t("OES_texture_float_linear"),t("EXT_color_buffer_half_float"),t("WEBGL_multisampled_render_to_texture"),t("WEBGL_render_shared_exponent")},get:function(i){let s=t(i);return s===null&&xa("WebGLRenderer: "+i+" extension not supported."),s}}}function ZM(n,e,t,i){let s={},r=new WeakMap,o=new FinalizationRegistry(g=>delete s[g]);function a(g){l(g.target)}function l(g){g.index!==null&&e.remove(g.index);for(let d in g.attributes)e.remove(g.attributes[d]);g.removeEventListener("dispose",a),delete s[g.id],o.unregister(g);let S=r.get(g);S&&(e.remove(S),r.delete(g)),i.releaseStatesOfGeometry(g),g.isInstancedBufferGeometry===!0&&delete g._maxInstanceCount,t.memory.geometries--}function c(g,S){return s[S.id]!==void 0||(S.addEventListener("dispose",a),s[S.id]=new WeakRef(S),o.register(S,S.id,S),t.memory.geometries++),S}function h(g){let S=g.attributes;for(let d in S)e.update(S[d],n.ARRAY_BUFFER)}function f(g){let S=g.index,d=g.attributes.position,m=0;if(d===void 0)return;let y=S!==null?S.array.length:d.array.length/3-1,A=d.count>=65535?Ia:Ca,b=new A(Math.ceil(y/3)*6,1),C=b.array;if(S!==null){let x=S.array;m=S.version;for(let T=0,k=0;T<y;T+=3){let U=x[T+0],P=x[T+1],B=x[T+2];C[k++]=U,C[k++]=P,C[k++]=P,C[k++]=B,C[k++]=B,C[k++]=U}}else{m=d.version;for(let x=0,T=0;x<y;x+=3){let k=x+0,U=x+1,P=x+2;C[T++]=k,C[T++]=U,C[T++]=U,C[T++]=P,C[T++]=P,C[T++]=k}}b.version=m;let E=r.get(g);E&&e.remove(E),r.set(g,b)}function u(g){let S=r.get(g);if(S){let d=g.index;d!==null&&S.version<d.version&&f(g)}else f(g);return r.get(g)}function p(){for(let g in s){let S=s[g].deref();S!==void 0&&l(S)}}return{get:c,update:h,getWireframeAttribute:u,dispose:p}}function KM(n,e,t){let i;function s(f){i=f}let r,o;function a(f){r=f.type,o=f.bytesPerElement}function l(f,u){n.drawElements(i,u,r,f*o),t.update(u,i,1)}function c(f,u,p){p!==0&&(n.drawElementsInstanced(i,u,r,f*o,p),t.update(u,i,p))}function h(f,u,p){if(p===0)return;e.get("WEBGL_multi_draw").multiDrawElementsWEBGL(i,u,0,r,f,0,p);let S=0;for(let d=0;d<p;d++)S+=u[d];t.update(S,i,1)}this.setMode=s,this.setIndex=a,this.render=l,this.renderInstances=c,this.renderMultiDraw=h}function JM(n){let e={geometries:0,textures:0},t={frame:0,calls:0,triangles:0,points:0,lines:0};function i(r,o,a){switch(t.calls++,o){case n.TRIANGLES:t.triangles+=a*(r/3);break;case n.LINES:t.lines+=a*(r/2);break;case n.LINE_STRIP:t.lines+=a*(r-1);break;case n.LINE_LOOP:t.lines+=a*r;break;case n.POINTS:t.points+=a*r;break;default:rt("WebGLInfo: Unknown draw mode:",o);break}}function s(){t.calls=0,t.triangles=0,t.points=0,t.lines=0}return{memory:e,render:t,programs:null,autoReset:!0,reset:s,update:i}}function jM(n,e,t){let i=new WeakMap,s=new sn;function r(o,a,l){let c=o.morphTargetInfluences,h=a.morphAttributes.position||a.morphAttributes.normal||a.morphAttributes.color,f=h!==void 0?h.length:0,u=i.get(a);if(u===void 0||u.count!==f){let k=function(){x.dispose(),i.delete(a),a.removeEventListener("dispose",k)};u!==void 0&&u.texture.dispose();let p=a.morphAttributes.position!==void 0,g=a.morphAttributes.normal!==void 0,S=a.morphAttributes.color!==void 0,d=a.morphAttributes.position||[],m=a.morphAttributes.normal||[],y=a.morphAttributes.color||[],A=0;p===!0&&(A=1),g===!0&&(A=2),S===!0&&(A=3);let b=a.attributes.position.count*A,C=1;b>e.maxTextureSize&&(C=Math.ceil(b/e.maxTextureSize),b=e.maxTextureSize);let E=new Float32Array(b*C*4*f),x=new Ta(E,b,C,f);x.type=Oi,x.needsUpdate=!0;let T=A*4;for(let U=0;U<f;U++){let P=d[U],B=m[U],z=y[U],L=b*C*4*U;for(let H=0;H<P.count;H++){let W=H*T;p===!0&&(s.fromBufferAttribute(P,H),E[L+W+0]=s.x,E[L+W+1]=s.y,E[L+W+2]=s.z,E[L+W+3]=0),g===!0&&(s.fromBufferAttribute(B,H),E[L+W+4]=s.x,E[L+W+5]=s.y,E[L+W+6]=s.z,E[L+W+7]=0),S===!0&&(s.fromBufferAttribute(z,H),E[L+W+8]=s.x,E[L+W+9]=s.y,E[L+W+10]=s.z,E[L+W+11]=z.itemSize===4?s.w:1)}}u={count:f,texture:x,size:new ut(b,C)},i.set(a,u),a.addEventListener("dispose",k)}if(o.isInstancedMesh===!0&&o.morphTexture!==null)l.getUniforms().setValue(n,"morphTexture",o.morphTexture,t);else{let p=0;for(let S=0;S<c.length;S++)p+=c[S];let g=a.morphTargetsRelative?1:1-p;l.getUniforms().setValue(n,"morphTargetBaseInfluence",g),l.getUniforms().setValue(n,"morphTargetInfluences",c)}l.getUniforms().setValue(n,"morphTargetsTexture",u.texture,t),l.getUniforms().setValue(n,"morphTargetsTextureSize",u.size)}return{update:r}}function QM(n,e,t,i,s){let r=new WeakMap;function o(c){let h=s.render.frame,f=c.geometry,u=e.get(c,f);if(r.get(u)!==h&&(e.update(u),r.set(u,h)),c.isInstancedMesh&&(c.hasEventListener("dispose",l)===!1&&c.addEventListener("dispose",l),r.get(c)!==h&&(t.update(c.instanceMatrix,n.ARRAY_BUFFER),c.instanceColor!==null&&t.update(c.instanceColor,n.ARRAY_BUFFER),r.set(c,h))),c.isSkinnedMesh){let p=c.skeleton;r.get(p)!==h&&(p.update(),r.set(p,h))}return u}function a(){r=new WeakMap}function l(c){let h=c.target;h.removeEventListener("dispose",l),i.releaseStatesOfObject(h),t.remove(h.instanceMatrix),h.instanceColor!==null&&t.remove(h.instanceColor)}return{update:o,dispose:a}}var ew={[Of]:"LINEAR_TONE_MAPPING",[Ff]:"REINHARD_TONE_MAPPING",[Bf]:"CINEON_TONE_MAPPING",[kf]:"ACES_FILMIC_TONE_MAPPING",[Gf]:"AGX_TONE_MAPPING",[Hf]:"NEUTRAL_TONE_MAPPING",[zf]:"CUSTOM_TONE_MAPPING"};function tw(n,e,t,i,s,r){let o=new pi(e,t,{type:n,depthBuffer:s,stencilBuffer:r,samples:i?4:0,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,resolveDepthBuffer:!1,resolveStencilBuffer:!1}),a=null,l=null,c=null,h=new jn;h.setAttribute("position",new Pn([-1,3,0,-1,-1,0,3,-1,0],3)),h.setAttribute("uv",new Pn([0,2,0,0,2,0],2));let f=new Nc({uniforms:{tDiffuse:{value:null}},vertexShader:`
			precision highp float;

			uniform mat4 modelViewMatrix;
			uniform mat4 projectionMatrix;

			attribute vec3 position;
			attribute vec2 uv;

			varying vec2 vUv;

			void main() {
				vUv = uv;
				gl_Position = projectionMatrix * modelViewMatrix * vec4( position, 1.0 );
			}`,fragmentShader:`
			precision highp float;

			uniform sampler2D tDiffuse;

			varying vec2 vUv;

			#include <tonemapping_pars_fragment>
			#include <colorspace_pars_fragment>

			void main() {
				gl_FragColor = texture2D( tDiffuse, vUv );

				#ifdef LINEAR_TONE_MAPPING
					gl_FragColor.rgb = LinearToneMapping( gl_FragColor.rgb );
				#elif defined( REINHARD_TONE_MAPPING )
					gl_FragColor.rgb = ReinhardToneMapping( gl_FragColor.rgb );
				#elif defined( CINEON_TONE_MAPPING )
					gl_FragColor.rgb = CineonToneMapping( gl_FragColor.rgb );
				#elif defined( ACES_FILMIC_TONE_MAPPING )
					gl_FragColor.rgb = ACESFilmicToneMapping( gl_FragColor.rgb );
				#elif defined( AGX_TONE_MAPPING )
					gl_FragColor.rgb = AgXToneMapping( gl_FragColor.rgb );
				#elif defined( NEUTRAL_TONE_MAPPING )
					gl_FragColor.rgb = NeutralToneMapping( gl_FragColor.rgb );
				#elif defined( CUSTOM_TONE_MAPPING )
					gl_FragColor.rgb = CustomToneMapping( gl_FragColor.rgb );
				#endif

				#ifdef SRGB_TRANSFER
					gl_FragColor = sRGBTransferOETF( gl_FragColor );
				#endif
			}`,depthTest:!1,depthWrite:!1}),u=new ji(h,f),p=new qc(-1,1,1,-1,0,1),g=null,S=null,d=!1,m,y=null,A=[],b=!1;this.setSize=function(C,E){o.setSize(C,E),a!==null&&a.setSize(C,E),l!==null&&l.setSize(C,E);for(let x=0;x<A.length;x++){let T=A[x];T.setSize&&T.setSize(C,E)}},this.setEffects=function(C){A=C,b=A.length>0&&A[0].isRenderPass===!0;let E=o.width,x=o.height;A.length>0&&a===null&&(a=new pi(E,x,{type:Fi,depthBuffer:!1,stencilBuffer:!1}),l=new pi(E,x,{type:Fi,depthBuffer:!1,stencilBuffer:!1}));let T=s===!0&&A.some(k=>k.needsDepthTexture===!0);T!==(o.depthTexture!==null)&&(T===!0&&c===null&&(c=new Ms(E,x),r===!0&&(c.format=Es,c.type=Pr)),o.dispose(),o.depthTexture=T?c:null,o.resolveDepthBuffer=T,o.storeMultisampledDepthBuffer=T);for(let k=0;k<A.length;k++){let U=A[k];U.setSize&&U.setSize(E,x),T&&U.needsDepthTexture===!0&&U.setDepthTexture&&U.setDepthTexture(c)}},this.begin=function(C,E){if(d||C.toneMapping===ts&&A.length===0)return!1;if(y=E,E!==null){let x=E.width,T=E.height;(o.width!==x||o.height!==T)&&this.setSize(x,T)}return b===!1&&C.setRenderTarget(o),m=C.toneMapping,C.toneMapping=ts,!0},this.hasRenderPass=function(){return b},this.end=function(C,E){C.toneMapping=m,d=!0;let x=o,T=a;for(let k=0;k<A.length;k++){let U=A[k];U.enabled!==!1&&(U.render(C,T,x,E),U.needsSwap!==!1&&(x=T,T=T===a?l:a))}if(g!==C.outputColorSpace||S!==C.toneMapping){g=C.outputColorSpace,S=C.toneMapping,f.defines={},At.getTransfer(g)===Ft&&(f.defines.SRGB_TRANSFER="");let k=ew[S];k&&(f.defines[k]=""),f.needsUpdate=!0}f.uniforms.tDiffuse.value=x.texture,C.setRenderTarget(y),C.render(u,p),y=null,d=!1},this.isCompositing=function(){return d},this.dispose=function(){o.dispose(),a!==null&&a.dispose(),l!==null&&l.dispose(),h.dispose(),f.dispose()}}var n_=new Kn,i_=new Ms(1,1),s_=new Da(1),r_=new Ta,o_=new Tc,a_=new Na,U0=[],O0=[],F0=new Float32Array(16),B0=new Float32Array(9),k0=new Float32Array(4);function Bo(n,e,t){let i=n[0];if(i<=0||i>0)return n;let s=e*t,r=U0[s];if(r===void 0&&(r=new Float32Array(s),U0[s]=r),e!==0){i.toArray(r,0);for(let o=1,a=0;o!==e;++o)a+=t,n[o].toArray(r,a)}return r}function bn(n,e){if(n.length!==e.length)return!1;for(let t=0,i=n.length;t<i;t++)if(n[t]!==e[t])return!1;return!0}function Mn(n,e){for(let t=0,i=e.length;t<i;t++)n[t]=e[t]}function Bh(n,e){let t=O0[e];t===void 0&&(t=new Int32Array(e),O0[e]=t);for(let i=0;i!==e;++i)t[i]=n.allocateTextureUnit();return t}function nw(n,e){let t=this.cache;t[0]!==e&&(n.uniform1f(this.addr,e),t[0]=e)}function iw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2f(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(bn(t,e))return;n.uniform2fv(this.addr,e),Mn(t,e)}}function sw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3f(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else if(e.r!==void 0)(t[0]!==e.r||t[1]!==e.g||t[2]!==e.b)&&(n.uniform3f(this.addr,e.r,e.g,e.b),t[0]=e.r,t[1]=e.g,t[2]=e.b);else{if(bn(t,e))return;n.uniform3fv(this.addr,e),Mn(t,e)}}function rw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4f(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(bn(t,e))return;n.uniform4fv(this.addr,e),Mn(t,e)}}function ow(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(bn(t,e))return;n.uniformMatrix2fv(this.addr,!1,e),Mn(t,e)}else{if(bn(t,i))return;k0.set(i),n.uniformMatrix2fv(this.addr,!1,k0),Mn(t,i)}}function aw(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(bn(t,e))return;n.uniformMatrix3fv(this.addr,!1,e),Mn(t,e)}else{if(bn(t,i))return;B0.set(i),n.uniformMatrix3fv(this.addr,!1,B0),Mn(t,i)}}function lw(n,e){let t=this.cache,i=e.elements;if(i===void 0){if(bn(t,e))return;n.uniformMatrix4fv(this.addr,!1,e),Mn(t,e)}else{if(bn(t,i))return;F0.set(i),n.uniformMatrix4fv(this.addr,!1,F0),Mn(t,i)}}function cw(n,e){let t=this.cache;t[0]!==e&&(n.uniform1i(this.addr,e),t[0]=e)}function hw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2i(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(bn(t,e))return;n.uniform2iv(this.addr,e),Mn(t,e)}}function uw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3i(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(bn(t,e))return;n.uniform3iv(this.addr,e),Mn(t,e)}}function fw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4i(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(bn(t,e))return;n.uniform4iv(this.addr,e),Mn(t,e)}}function dw(n,e){let t=this.cache;t[0]!==e&&(n.uniform1ui(this.addr,e),t[0]=e)}function pw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y)&&(n.uniform2ui(this.addr,e.x,e.y),t[0]=e.x,t[1]=e.y);else{if(bn(t,e))return;n.uniform2uiv(this.addr,e),Mn(t,e)}}function mw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z)&&(n.uniform3ui(this.addr,e.x,e.y,e.z),t[0]=e.x,t[1]=e.y,t[2]=e.z);else{if(bn(t,e))return;n.uniform3uiv(this.addr,e),Mn(t,e)}}function gw(n,e){let t=this.cache;if(e.x!==void 0)(t[0]!==e.x||t[1]!==e.y||t[2]!==e.z||t[3]!==e.w)&&(n.uniform4ui(this.addr,e.x,e.y,e.z,e.w),t[0]=e.x,t[1]=e.y,t[2]=e.z,t[3]=e.w);else{if(bn(t,e))return;n.uniform4uiv(this.addr,e),Mn(t,e)}}function kh(n){return n.version===0&&(n.compareFunction=ed,n.needsUpdate=!0),n}function _w(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s);let r;this.type===n.SAMPLER_2D_SHADOW?r=kh(i_):r=n_,t.setTexture2D(e||r,s)}function xw(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s),t.setTexture3D(e||o_,s)}function yw(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s);let r;this.type===n.SAMPLER_CUBE_SHADOW?r=kh(s_):r=a_,t.setTextureCube(e||r,s)}function vw(n,e,t){let i=this.cache,s=t.allocateTextureUnit();i[0]!==s&&(n.uniform1i(this.addr,s),i[0]=s),t.setTexture2DArray(e||r_,s)}function Sw(n){switch(n){case 5126:return nw;case 35664:return iw;case 35665:return sw;case 35666:return rw;case 35674:return ow;case 35675:return aw;case 35676:return lw;case 5124:case 35670:return cw;case 35667:case 35671:return hw;case 35668:case 35672:return uw;case 35669:case 35673:return fw;case 5125:return dw;case 36294:return pw;case 36295:return mw;case 36296:return gw;case 35678:case 36198:case 36298:case 36306:case 35682:return _w;case 35679:case 36299:case 36307:return xw;case 35680:case 36300:case 36308:case 36293:return yw;case 36289:case 36303:case 36311:case 36292:return vw}}function bw(n,e){n.uniform1fv(this.addr,e)}function Mw(n,e){let t=Bo(e,this.size,2);n.uniform2fv(this.addr,t)}function ww(n,e){let t=Bo(e,this.size,3);n.uniform3fv(this.addr,t)}function Ew(n,e){let t=Bo(e,this.size,4);n.uniform4fv(this.addr,t)}function Tw(n,e){let t=Bo(e,this.size,4);n.uniformMatrix2fv(this.addr,!1,t)}function Aw(n,e){let t=Bo(e,this.size,9);n.uniformMatrix3fv(this.addr,!1,t)}function Rw(n,e){let t=Bo(e,this.size,16);n.uniformMatrix4fv(this.addr,!1,t)}function Cw(n,e){n.uniform1iv(this.addr,e)}function Iw(n,e){n.uniform2iv(this.addr,e)}function Pw(n,e){n.uniform3iv(this.addr,e)}function Lw(n,e){n.uniform4iv(this.addr,e)}function Nw(n,e){n.uniform1uiv(this.addr,e)}function Dw(n,e){n.uniform2uiv(this.addr,e)}function Uw(n,e){n.uniform3uiv(this.addr,e)}function Ow(n,e){n.uniform4uiv(this.addr,e)}function Fw(n,e,t){let i=this.cache,s=e.length,r=Bh(t,s);bn(i,r)||(n.uniform1iv(this.addr,r),Mn(i,r));let o;this.type===n.SAMPLER_2D_SHADOW?o=kh(i_):o=n_;for(let a=0;a!==s;++a)t.setTexture2D(e[a]||o,r[a])}function Bw(n,e,t){let i=this.cache,s=e.length,r=Bh(t,s);bn(i,r)||(n.uniform1iv(this.addr,r),Mn(i,r));for(let o=0;o!==s;++o)t.setTexture3D(e[o]||o_,r[o])}function kw(n,e,t){let i=this.cache,s=e.length,r=Bh(t,s);bn(i,r)||(n.uniform1iv(this.addr,r),Mn(i,r));let o;this.type===n.SAMPLER_CUBE_SHADOW?o=kh(s_):o=a_;for(let a=0;a!==s;++a)t.setTextureCube(e[a]||o,r[a])}function zw(n,e,t){let i=this.cache,s=e.length,r=Bh(t,s);bn(i,r)||(n.uniform1iv(this.addr,r),Mn(i,r));for(let o=0;o!==s;++o)t.setTexture2DArray(e[o]||r_,r[o])}function Gw(n){switch(n){case 5126:return bw;case 35664:return Mw;case 35665:return ww;case 35666:return Ew;case 35674:return Tw;case 35675:return Aw;case 35676:return Rw;case 5124:case 35670:return Cw;case 35667:case 35671:return Iw;case 35668:case 35672:return Pw;case 35669:case 35673:return Lw;case 5125:return Nw;case 36294:return Dw;case 36295:return Uw;case 36296:return Ow;case 35678:case 36198:case 36298:case 36306:case 35682:return Fw;case 35679:case 36299:case 36307:return Bw;case 35680:case 36300:case 36308:case 36293:return kw;case 36289:case 36303:case 36311:case 36292:return zw}}var xd=class{constructor(e,t,i){this.id=e,this.addr=i,this.cache=[],this.type=t.type,this.setValue=Sw(t.type)}},yd=class{constructor(e,t,i){this.id=e,this.addr=i,this.cache=[],this.type=t.type,this.size=t.size,this.setValue=Gw(t.type)}},vd=class{constructor(e){this.id=e,this.seq=[],this.map={}}setValue(e,t,i){let s=this.seq;for(let r=0,o=s.length;r!==o;++r){let a=s[r];a.setValue(e,t[a.id],i)}}},gd=/(\w+)(\])?(\[|\.)?/g;function z0(n,e){n.seq.push(e),n.map[e.id]=e}function Hw(n,e,t){let i=n.name,s=i.length;for(gd.lastIndex=0;;){let r=gd.exec(i),o=gd.lastIndex,a=r[1],l=r[2]==="]",c=r[3];if(l&&(a=a|0),c===void 0||c==="["&&o+2===s){z0(t,c===void 0?new xd(a,n,e):new yd(a,n,e));break}else{let f=t.map[a];f===void 0&&(f=new vd(a),z0(t,f)),t=f}}}var Fo=class{constructor(e,t){this.seq=[],this.map={};let i=e.getProgramParameter(t,e.ACTIVE_UNIFORMS);for(let o=0;o<i;++o){let a=e.getActiveUniform(t,o),l=e.getUniformLocation(t,a.name);Hw(a,l,this)}let s=[],r=[];for(let o of this.seq)o.type===e.SAMPLER_2D_SHADOW||o.type===e.SAMPLER_CUBE_SHADOW||o.type===e.SAMPLER_2D_ARRAY_SHADOW?s.push(o):r.push(o);s.length>0&&(this.seq=s.concat(r))}setValue(e,t,i,s){let r=this.map[t];r!==void 0&&r.setValue(e,i,s)}setOptional(e,t,i){let s=t[i];s!==void 0&&this.setValue(e,i,s)}static upload(e,t,i,s){for(let r=0,o=t.length;r!==o;++r){let a=t[r],l=i[a.id];l.needsUpdate!==!1&&a.setValue(e,l.value,s)}}static seqWithValue(e,t){let i=[];for(let s=0,r=e.length;s!==r;++s){let o=e[s];o.id in t&&i.push(o)}return i}};function G0(n,e,t){let i=n.createShader(e);return n.shaderSource(i,t),n.compileShader(i),i}var Vw=37297,Ww=0;function Xw(n,e){let t=n.split(`
`),i=[],s=Math.max(e-6,0),r=Math.min(e+6,t.length);for(let o=s;o<r;o++){let a=o+1;i.push(`${a===e?">":" "} ${a}: ${t[o]}`)}return i.join(`
`)}var H0=new ot;function qw(n){At._getMatrix(H0,At.workingColorSpace,n);let e=`mat3( ${H0.elements.map(t=>t.toFixed(4))} )`;switch(At.getTransfer(n)){case Ma:return[e,"LinearTransferOETF"];case Ft:return[e,"sRGBTransferOETF"];default:return Je("WebGLProgram: Unsupported color space: ",n),[e,"LinearTransferOETF"]}}function V0(n,e,t){let i=n.getShaderParameter(e,n.COMPILE_STATUS),r=(n.getShaderInfoLog(e)||"").trim();if(i&&r==="")return"";let o=/ERROR: 0:(\d+)/.exec(r);if(o){let a=parseInt(o[1]);return t.toUpperCase()+`

`+r+`

`+Xw(n.getShaderSource(e),a)}else return r}function Yw(n,e){let t=qw(e);return[`vec4 ${n}( vec4 value ) {`,`	return ${t[1]}( vec4( ${t[0]} * value.rgb, value.a ) );`,"}"].join(`
`)}var $w={[Of]:"Linear",[Ff]:"Reinhard",[Bf]:"Cineon",[kf]:"ACESFilmic",[Gf]:"AgX",[Hf]:"Neutral",[zf]:"Custom"};function Zw(n,e){let t=$w[e];return t===void 0?(Je("WebGLProgram: Unsupported toneMapping:",e),"vec3 "+n+"( vec3 color ) { return LinearToneMapping( color ); }"):"vec3 "+n+"( vec3 color ) { return "+t+"ToneMapping( color ); }"}var Uh=new K;function Kw(){At.getLuminanceCoefficients(Uh);let n=Uh.x.toFixed(4),e=Uh.y.toFixed(4),t=Uh.z.toFixed(4);return["float luminance( const in vec3 rgb ) {",`	const vec3 weights = vec3( ${n}, ${e}, ${t} );`,"	return dot( weights, rgb );","}"].join(`
`)}function Jw(n){return[n.extensionClipCullDistance?"#extension GL_ANGLE_clip_cull_distance : require":"",n.extensionMultiDraw?"#extension GL_ANGLE_multi_draw : require":""].filter(Ja).join(`
`)}function jw(n){let e=[];for(let t in n){let i=n[t];i!==!1&&e.push("#define "+t+" "+i)}return e.join(`
`)}function Qw(n,e){let t={},i=n.getProgramParameter(e,n.ACTIVE_ATTRIBUTES);for(let s=0;s<i;s++){let r=n.getActiveAttrib(e,s),o=r.name,a=1;r.type===n.FLOAT_MAT2&&(a=2),r.type===n.FLOAT_MAT3&&(a=3),r.type===n.FLOAT_MAT4&&(a=4),t[o]={type:r.type,location:n.getAttribLocation(e,o),locationSize:a}}return t}function Ja(n){return n!==""}function W0(n,e){let t=e.numSpotLightShadows+e.numSpotLightMaps-e.numSpotLightShadowsWithMaps;return n.replace(/NUM_SUN_LIGHTS/g,e.numSunLights).replace(/NUM_DIR_LIGHTS/g,e.numDirLights).replace(/NUM_SPOT_LIGHTS/g,e.numSpotLights).replace(/NUM_SPOT_LIGHT_MAPS/g,e.numSpotLightMaps).replace(/NUM_SPOT_LIGHT_COORDS/g,t).replace(/NUM_RECT_AREA_LIGHTS/g,e.numRectAreaLights).replace(/NUM_POINT_LIGHTS/g,e.numPointLights).replace(/NUM_HEMI_LIGHTS/g,e.numHemiLights).replace(/NUM_SUN_LIGHT_SHADOWS/g,e.numSunLightShadows).replace(/NUM_DIR_LIGHT_SHADOWS/g,e.numDirLightShadows).replace(/NUM_SPOT_LIGHT_SHADOWS_WITH_MAPS/g,e.numSpotLightShadowsWithMaps).replace(/NUM_SPOT_LIGHT_SHADOWS/g,e.numSpotLightShadows).replace(/NUM_POINT_LIGHT_SHADOWS/g,e.numPointLightShadows).replace(/NUM_LIGHT_PROBE_GRIDS/g,e.numLightProbeGrids)}function X0(n,e){return n.replace(/NUM_CLIPPING_PLANES/g,e.numClippingPlanes).replace(/UNION_CLIPPING_PLANES/g,e.numClippingPlanes-e.numClipIntersection)}var eE=/^[ \t]*#include +<([\w\d./]+)>/gm;function Sd(n){return n.replace(eE,tE)}function tE(n,e){let t=_t[e];if(t===void 0)throw new Error("THREE.WebGLProgram: Can not resolve #include <"+e+">");return Sd(t)}var nE=/#pragma unroll_loop_start\s+for\s*\(\s*int\s+i\s*=\s*(\d+)\s*;\s*i\s*<\s*(\d+)\s*;\s*i\s*\+\+\s*\)\s*{([\s\S]+?)}\s+#pragma unroll_loop_end/g;function q0(n){return n.replace(nE,iE)}function iE(n,e,t,i){let s="";for(let r=parseInt(e);r<parseInt(t);r++)s+=i.replace(/\[\s*i\s*\]/g,"[ "+r+" ]").replace(/UNROLLED_LOOP_INDEX/g,r);return s}function Y0(n){let e=`precision ${n.precision} float;
	precision ${n.precision} int;
	precision ${n.precision} sampler2D;
	precision ${n.precision} samplerCube;
	precision ${n.precision} sampler3D;
	precision ${n.precision} sampler2DArray;
	precision ${n.precision} sampler2DShadow;
	precision ${n.precision} samplerCubeShadow;
	precision ${n.precision} sampler2DArrayShadow;
	precision ${n.precision} isampler2D;
	precision ${n.precision} isampler3D;
	precision ${n.precision} isamplerCube;
	precision ${n.precision} isampler2DArray;
	precision ${n.precision} usampler2D;
	precision ${n.precision} usampler3D;
	precision ${n.precision} usamplerCube;
	precision ${n.precision} usampler2DArray;
	`;return n.precision==="highp"?e+=`
#define HIGH_PRECISION`:n.precision==="mediump"?e+=`
#define MEDIUM_PRECISION`:n.precision==="lowp"&&(e+=`
#define LOW_PRECISION`),e}var sE={[Ha]:"SHADOWMAP_TYPE_PCF",[Lo]:"SHADOWMAP_TYPE_VSM"};function rE(n){return sE[n.shadowMapType]||"SHADOWMAP_TYPE_BASIC"}var oE={[Do]:"ENVMAP_MODE_REFRACTION"};function aE(n){return n.envMap===!1?"ENVMAP_MODE_REFLECTION":oE[n.envMapMode]||"ENVMAP_MODE_REFLECTION"}var lE={[Uf]:"ENVMAP_BLENDING_MULTIPLY",[c0]:"ENVMAP_BLENDING_MIX",[h0]:"ENVMAP_BLENDING_ADD"};function cE(n){return n.envMap===!1?"ENVMAP_BLENDING_NONE":lE[n.combine]||"ENVMAP_BLENDING_NONE"}function hE(n,e,t,i){let s=n.getContext(),r=t.defines,o=t.vertexShader,a=t.fragmentShader,l=rE(t),c=t.envMapPMREM===!0?"ENVMAP_TYPE_PMREM":"ENVMAP_TYPE_CUBE",h=aE(t),f=cE(t),u=Jw(t),p=jw(r),g=s.createProgram(),S,d,m=t.glslVersion?"#version "+t.glslVersion+`
`:"";t.isRawShaderMaterial?(S=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,p].filter(Ja).join(`
`),S.length>0&&(S+=`
`),d=["#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,p].filter(Ja).join(`
`),d.length>0&&(d+=`
`)):(S=[Y0(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,p,t.extensionClipCullDistance?"#define USE_CLIP_DISTANCE":"",t.batching?"#define USE_BATCHING":"",t.batchingColor?"#define USE_BATCHING_COLOR":"",t.instancing?"#define USE_INSTANCING":"",t.instancingColor?"#define USE_INSTANCING_COLOR":"",t.instancingMorph?"#define USE_INSTANCING_MORPH":"",t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.map?"#define USE_MAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+h:"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.displacementMap?"#define USE_DISPLACEMENTMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.mapUv?"#define MAP_UV "+t.mapUv:"",t.alphaMapUv?"#define ALPHAMAP_UV "+t.alphaMapUv:"",t.lightMapUv?"#define LIGHTMAP_UV "+t.lightMapUv:"",t.aoMapUv?"#define AOMAP_UV "+t.aoMapUv:"",t.emissiveMapUv?"#define EMISSIVEMAP_UV "+t.emissiveMapUv:"",t.bumpMapUv?"#define BUMPMAP_UV "+t.bumpMapUv:"",t.normalMapUv?"#define NORMALMAP_UV "+t.normalMapUv:"",t.displacementMapUv?"#define DISPLACEMENTMAP_UV "+t.displacementMapUv:"",t.metalnessMapUv?"#define METALNESSMAP_UV "+t.metalnessMapUv:"",t.roughnessMapUv?"#define ROUGHNESSMAP_UV "+t.roughnessMapUv:"",t.anisotropyMapUv?"#define ANISOTROPYMAP_UV "+t.anisotropyMapUv:"",t.clearcoatMapUv?"#define CLEARCOATMAP_UV "+t.clearcoatMapUv:"",t.clearcoatNormalMapUv?"#define CLEARCOAT_NORMALMAP_UV "+t.clearcoatNormalMapUv:"",t.clearcoatRoughnessMapUv?"#define CLEARCOAT_ROUGHNESSMAP_UV "+t.clearcoatRoughnessMapUv:"",t.diffuseRoughnessMapUv?"#define DIFFUSE_ROUGHNESSMAP_UV "+t.diffuseRoughnessMapUv:"",t.iridescenceMapUv?"#define IRIDESCENCEMAP_UV "+t.iridescenceMapUv:"",t.iridescenceThicknessMapUv?"#define IRIDESCENCE_THICKNESSMAP_UV "+t.iridescenceThicknessMapUv:"",t.sheenColorMapUv?"#define SHEEN_COLORMAP_UV "+t.sheenColorMapUv:"",t.sheenRoughnessMapUv?"#define SHEEN_ROUGHNESSMAP_UV "+t.sheenRoughnessMapUv:"",t.specularMapUv?"#define SPECULARMAP_UV "+t.specularMapUv:"",t.specularColorMapUv?"#define SPECULAR_COLORMAP_UV "+t.specularColorMapUv:"",t.specularIntensityMapUv?"#define SPECULAR_INTENSITYMAP_UV "+t.specularIntensityMapUv:"",t.transmissionMapUv?"#define TRANSMISSIONMAP_UV "+t.transmissionMapUv:"",t.thicknessMapUv?"#define THICKNESSMAP_UV "+t.thicknessMapUv:"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexNormals?"#define HAS_NORMAL":"",t.vertexColors?"#define USE_COLOR":"",t.vertexAlphas?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.flatShading?"#define FLAT_SHADED":"",t.skinning?"#define USE_SKINNING":"",t.morphTargets?"#define USE_MORPHTARGETS":"",t.morphNormals&&t.flatShading===!1?"#define USE_MORPHNORMALS":"",t.morphColors?"#define USE_MORPHCOLORS":"",t.morphTargetsCount>0?"#define MORPHTARGETS_TEXTURE_STRIDE "+t.morphTextureStride:"",t.morphTargetsCount>0?"#define MORPHTARGETS_COUNT "+t.morphTargetsCount:"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.sizeAttenuation?"#define USE_SIZEATTENUATION":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 modelMatrix;","uniform mat4 modelViewMatrix;","uniform mat4 projectionMatrix;","uniform mat4 viewMatrix;","uniform mat3 normalMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;","#ifdef USE_INSTANCING","	attribute mat4 instanceMatrix;","#endif","#ifdef USE_INSTANCING_COLOR","	attribute vec3 instanceColor;","#endif","#ifdef USE_INSTANCING_MORPH","	uniform sampler2D morphTexture;","#endif","attribute vec3 position;","attribute vec3 normal;","attribute vec2 uv;","#ifdef USE_UV1","	attribute vec2 uv1;","#endif","#ifdef USE_UV2","	attribute vec2 uv2;","#endif","#ifdef USE_UV3","	attribute vec2 uv3;","#endif","#ifdef USE_TANGENT","	attribute vec4 tangent;","#endif","#if defined( USE_COLOR_ALPHA )","	attribute vec4 color;","#elif defined( USE_COLOR )","	attribute vec3 color;","#endif","#ifdef USE_SKINNING","	attribute vec4 skinIndex;","	attribute vec4 skinWeight;","#endif",`
`].filter(Ja).join(`
`),d=[Y0(t),"#define SHADER_TYPE "+t.shaderType,"#define SHADER_NAME "+t.shaderName,p,t.useFog&&t.fog?"#define USE_FOG":"",t.useFog&&t.fogExp2?"#define FOG_EXP2":"",t.alphaToCoverage?"#define ALPHA_TO_COVERAGE":"",t.map?"#define USE_MAP":"",t.matcap?"#define USE_MATCAP":"",t.envMap?"#define USE_ENVMAP":"",t.envMap?"#define "+c:"",t.envMap?"#define "+h:"",t.envMap?"#define "+f:"",t.envMapPMREM?"#define ENVMAP_MAX_LOD "+t.envMapMaxLod+".0":"",t.envMapPMREM?"#define ENVMAP_SIZE "+t.envMapSize+".0":"",t.lightMap?"#define USE_LIGHTMAP":"",t.aoMap?"#define USE_AOMAP":"",t.bumpMap?"#define USE_BUMPMAP":"",t.normalMap?"#define USE_NORMALMAP":"",t.normalMapObjectSpace?"#define USE_NORMALMAP_OBJECTSPACE":"",t.normalMapTangentSpace?"#define USE_NORMALMAP_TANGENTSPACE":"",t.packedNormalMap?"#define USE_PACKED_NORMALMAP":"",t.emissiveMap?"#define USE_EMISSIVEMAP":"",t.anisotropy?"#define USE_ANISOTROPY":"",t.anisotropyMap?"#define USE_ANISOTROPYMAP":"",t.clearcoat?"#define USE_CLEARCOAT":"",t.clearcoatMap?"#define USE_CLEARCOATMAP":"",t.clearcoatRoughnessMap?"#define USE_CLEARCOAT_ROUGHNESSMAP":"",t.clearcoatNormalMap?"#define USE_CLEARCOAT_NORMALMAP":"",t.diffuseRoughness?"#define USE_DIFFUSE_ROUGHNESS":"",t.diffuseRoughnessMap?"#define USE_DIFFUSE_ROUGHNESSMAP":"",t.dispersion?"#define USE_DISPERSION":"",t.retroreflection?"#define USE_RETROREFLECTION":"",t.iridescence?"#define USE_IRIDESCENCE":"",t.iridescenceMap?"#define USE_IRIDESCENCEMAP":"",t.iridescenceThicknessMap?"#define USE_IRIDESCENCE_THICKNESSMAP":"",t.specularMap?"#define USE_SPECULARMAP":"",t.specularColorMap?"#define USE_SPECULAR_COLORMAP":"",t.specularIntensityMap?"#define USE_SPECULAR_INTENSITYMAP":"",t.roughnessMap?"#define USE_ROUGHNESSMAP":"",t.metalnessMap?"#define USE_METALNESSMAP":"",t.alphaMap?"#define USE_ALPHAMAP":"",t.alphaTest?"#define USE_ALPHATEST":"",t.alphaHash?"#define USE_ALPHAHASH":"",t.sheen?"#define USE_SHEEN":"",t.sheenColorMap?"#define USE_SHEEN_COLORMAP":"",t.sheenRoughnessMap?"#define USE_SHEEN_ROUGHNESSMAP":"",t.transmission?"#define USE_TRANSMISSION":"",t.transmissionMap?"#define USE_TRANSMISSIONMAP":"",t.thicknessMap?"#define USE_THICKNESSMAP":"",t.vertexTangents&&t.flatShading===!1?"#define USE_TANGENT":"",t.vertexColors||t.instancingColor?"#define USE_COLOR":"",t.vertexAlphas||t.batchingColor?"#define USE_COLOR_ALPHA":"",t.vertexUv1s?"#define USE_UV1":"",t.vertexUv2s?"#define USE_UV2":"",t.vertexUv3s?"#define USE_UV3":"",t.pointsUvs?"#define USE_POINTS_UV":"",t.gradientMap?"#define USE_GRADIENTMAP":"",t.flatShading?"#define FLAT_SHADED":"",t.doubleSided?"#define DOUBLE_SIDED":"",t.flipSided?"#define FLIP_SIDED":"",t.shadowMapEnabled?"#define USE_SHADOWMAP":"",t.shadowMapEnabled?"#define "+l:"",t.premultipliedAlpha?"#define PREMULTIPLIED_ALPHA":"",t.numLightProbes>0?"#define USE_LIGHT_PROBES":"",t.decodeVideoTexture?"#define DECODE_VIDEO_TEXTURE":"",t.decodeVideoTextureEmissive?"#define DECODE_VIDEO_TEXTURE_EMISSIVE":"",t.logarithmicDepthBuffer?"#define USE_LOGARITHMIC_DEPTH_BUFFER":"",t.reversedDepthBuffer?"#define USE_REVERSED_DEPTH_BUFFER":"","uniform mat4 viewMatrix;","uniform vec3 cameraPosition;","uniform bool isOrthographic;",t.toneMapping!==ts?"#define TONE_MAPPING":"",t.toneMapping!==ts?_t.tonemapping_pars_fragment:"",t.toneMapping!==ts?Zw("toneMapping",t.toneMapping):"",t.dithering?"#define DITHERING":"",t.opaque?"#define OPAQUE":"",_t.colorspace_pars_fragment,Yw("linearToOutputTexel",t.outputColorSpace),Kw(),t.useDepthPacking?"#define DEPTH_PACKING "+t.depthPacking:"",`
`].filter(Ja).join(`
`)),o=Sd(o),o=W0(o,t),o=X0(o,t),a=Sd(a),a=W0(a,t),a=X0(a,t),o=q0(o),a=q0(a),t.isRawShaderMaterial!==!0&&(m=`#version 300 es
`,S=[u,"#define attribute in","#define varying out","#define texture2D texture"].join(`
`)+`
`+S,d=["#define varying in",t.glslVersion===td?"":"layout(location = 0) out highp vec4 pc_fragColor;",t.glslVersion===td?"":"#define gl_FragColor pc_fragColor","#define gl_FragDepthEXT gl_FragDepth","#define texture2D texture","#define textureCube texture","#define texture2DProj textureProj","#define texture2DLodEXT textureLod","#define texture2DProjLodEXT textureProjLod","#define textureCubeLodEXT textureLod","#define texture2DGradEXT textureGrad","#define texture2DProjGradEXT textureProjGrad","#define textureCubeGradEXT textureGrad"].join(`
`)+`
`+d);let y=m+S+o,A=m+d+a,b=G0(s,s.VERTEX_SHADER,y),C=G0(s,s.FRAGMENT_SHADER,A);s.attachShader(g,b),s.attachShader(g,C),t.index0AttributeName!==void 0?s.bindAttribLocation(g,0,t.index0AttributeName):t.hasPositionAttribute===!0&&s.bindAttribLocation(g,0,"position"),s.linkProgram(g);function E(U){if(n.debug.checkShaderErrors){let P=s.getProgramInfoLog(g)||"",B=s.getShaderInfoLog(b)||"",z=s.getShaderInfoLog(C)||"",L=P.trim(),H=B.trim(),W=z.trim(),D=!0,te=!0;if(s.getProgramParameter(g,s.LINK_STATUS)===!1)if(D=!1,typeof n.debug.onShaderError=="function")n.debug.onShaderError(s,g,b,C);else{let X=V0(s,b,"vertex"),q=V0(s,C,"fragment");rt("WebGLProgram: Shader Error "+s.getError()+" - VALIDATE_STATUS "+s.getProgramParameter(g,s.VALIDATE_STATUS)+`

Material Name: `+U.name+`
Material Type: `+U.type+`

Program Info Log: `+L+`
`+X+`
`+q)}else L!==""?Je("WebGLProgram: Program Info Log:",L):(H===""||W==="")&&(te=!1);te&&(U.diagnostics={runnable:D,programLog:L,vertexShader:{log:H,prefix:S},fragmentShader:{log:W,prefix:d}})}s.deleteShader(b),s.deleteShader(C),x=new Fo(s,g),T=Qw(s,g)}let x;this.getUniforms=function(){return x===void 0&&E(this),x};let T;this.getAttributes=function(){return T===void 0&&E(this),T};let k=t.rendererExtensionParallelShaderCompile===!1;return this.isReady=function(){return k===!1&&(k=s.getProgramParameter(g,Vw)),k},this.destroy=function(){i.releaseStatesOfProgram(this),s.deleteProgram(g),this.program=void 0},this.type=t.shaderType,this.name=t.shaderName,this.id=Ww++,this.cacheKey=e,this.usedTimes=1,this.program=g,this.vertexShader=b,this.fragmentShader=C,this}var uE=0,bd=class{constructor(){this.shaderCache=new Map,this.materialCache=new Map}update(e,t,i){let s=this._getShaderCacheForMaterial(e);return s.has(t)===!1&&(s.add(t),t.usedTimes++),s.has(i)===!1&&(s.add(i),i.usedTimes++),this}remove(e){let t=this.materialCache.get(e);for(let i of t)i.usedTimes--,i.usedTimes===0&&this.shaderCache.delete(i.code);return this.materialCache.delete(e),this}getVertexShaderStage(e){return this._getShaderStage(e.vertexShader)}getFragmentShaderStage(e){return this._getShaderStage(e.fragmentShader)}dispose(){this.shaderCache.clear(),this.materialCache.clear()}_getShaderCacheForMaterial(e){let t=this.materialCache,i=t.get(e);return i===void 0&&(i=new Set,t.set(e,i)),i}_getShaderStage(e){let t=this.shaderCache,i=t.get(e);return i===void 0&&(i=new Md(e),t.set(e,i)),i}},Md=class{constructor(e){this.id=uE++,this.code=e,this.usedTimes=0}};function fE(n){return n===or||n===$a||n===Za}function dE(n,e,t,i,s,r){let o=new Aa,a=new bd,l=new Set,c=[],h=new Map,f=i.logarithmicDepthBuffer,u={MeshDepthMaterial:"depth",MeshDistanceMaterial:"distance",MeshNormalMaterial:"normal",MeshBasicMaterial:"basic",MeshLambertMaterial:"lambert",MeshPhongMaterial:"phong",MeshToonMaterial:"toon",MeshStandardMaterial:"physical",MeshPhysicalMaterial:"physical",MeshMatcapMaterial:"matcap",LineBasicMaterial:"basic",LineDashedMaterial:"dashed",PointsMaterial:"points",ShadowMaterial:"shadow",SpriteMaterial:"sprite"};function p(x){return l.add(x),x===0?"uv":`uv${x}`}function g(x,T,k,U,P,B){let z=U.fog,L=P.geometry,H=x.isMeshStandardMaterial||x.isMeshLambertMaterial||x.isMeshPhongMaterial?U.environment:null,W=x.isMeshStandardMaterial||x.isMeshLambertMaterial&&!x.envMap||x.isMeshPhongMaterial&&!x.envMap,D=e.get(x.envMap||H,W),te=u[x.type],X=i.precision;x.precision!==null&&(X=i.getMaxPrecision(x.precision),X!==x.precision&&Je("WebGLProgram.getParameters:",x.precision,"not supported, using",X,"instead."));let q=L.morphAttributes.position||L.morphAttributes.normal||L.morphAttributes.color,j=q!==void 0?q.length:0,ae=0;L.morphAttributes.position!==void 0&&(ae=1),L.morphAttributes.normal!==void 0&&(ae=2),L.morphAttributes.color!==void 0&&(ae=3);let ce,ee,pe,fe;if(te){let Ie=is[te];ce=Ie.vertexShader,ee=Ie.fragmentShader}else{ce=x.vertexShader,ee=x.fragmentShader;let Ie=a.getVertexShaderStage(x),dt=a.getFragmentShaderStage(x);a.update(x,Ie,dt),pe=Ie.id,fe=dt.id}let Me=n.getRenderTarget(),ye=n.state.buffers.depth.getReversed(),qe=P.isInstancedMesh===!0,it=P.isBatchedMesh===!0,We=!!x.map,Ce=!!x.matcap,Ne=!!D,Be=Ne&&D.isPMREMTexture===!0,xt=!!x.aoMap,Rt=!!x.lightMap,Bt=!!x.bumpMap&&x.wireframe===!1,at=!!x.normalMap,Ct=!!x.displacementMap,Ze=!!x.emissiveMap,ft=!!x.metalnessMap,pt=!!x.roughnessMap,bt=x.anisotropy>0,O=x.clearcoat>0,Pe=x.diffuseRoughness>0,je=x.dispersion>0,ht=x.retroreflectivity>0,Ee=x.iridescence>0,Vt=x.sheen>0,Xe=x.transmission>0,Ke=bt&&!!x.anisotropyMap,R=O&&!!x.clearcoatMap,v=O&&!!x.clearcoatNormalMap,Y=O&&!!x.clearcoatRoughnessMap,ue=Pe&&!!x.diffuseRoughnessMap,oe=Ee&&!!x.iridescenceMap,ve=Ee&&!!x.iridescenceThicknessMap,Se=Vt&&!!x.sheenColorMap,ne=Vt&&!!x.sheenRoughnessMap,se=!!x.specularMap,me=!!x.specularColorMap,F=!!x.specularIntensityMap,re=Xe&&!!x.transmissionMap,ie=Xe&&!!x.thicknessMap,Te=!!x.gradientMap,xe=!!x.alphaMap,we=x.alphaTest>0,Ye=!!x.alphaHash,tt=!!x.extensions,he=ts;x.toneMapped&&(Me===null||Me.isXRRenderTarget===!0)&&(he=n.toneMapping);let Ge=Be?D.isCompressedCubeTexture?D.image[0].mipmaps:D.mipmaps:null,nt={shaderID:te,shaderType:x.type,shaderName:x.name,vertexShader:ce,fragmentShader:ee,defines:x.defines,customVertexShaderID:pe,customFragmentShaderID:fe,isRawShaderMaterial:x.isRawShaderMaterial===!0,glslVersion:x.glslVersion,precision:X,batching:it,batchingColor:it&&P._colorsTexture!==null,instancing:qe,instancingColor:qe&&P.instanceColor!==null,instancingMorph:qe&&P.morphTexture!==null,outputColorSpace:Me===null?n.outputColorSpace:Me.isXRRenderTarget===!0?Me.texture.colorSpace:At.workingColorSpace,alphaToCoverage:!!x.alphaToCoverage,map:We,matcap:Ce,envMap:Ne,envMapMode:Ne&&D.mapping,envMapPMREM:Be,envMapMaxLod:Be?Ge.length-1:null,envMapSize:Be?Ge[0].width:null,aoMap:xt,lightMap:Rt,bumpMap:Bt,normalMap:at,displacementMap:Ct,emissiveMap:Ze,normalMapObjectSpace:at&&x.normalMapType===d0,normalMapTangentSpace:at&&x.normalMapType===Jf,packedNormalMap:at&&x.normalMapType===Jf&&fE(x.normalMap.format),metalnessMap:ft,roughnessMap:pt,anisotropy:bt,anisotropyMap:Ke,clearcoat:O,clearcoatMap:R,clearcoatNormalMap:v,clearcoatRoughnessMap:Y,diffuseRoughness:Pe,diffuseRoughnessMap:ue,dispersion:je,retroreflection:ht,iridescence:Ee,iridescenceMap:oe,iridescenceThicknessMap:ve,sheen:Vt,sheenColorMap:Se,sheenRoughnessMap:ne,specularMap:se,specularColorMap:me,specularIntensityMap:F,transmission:Xe,transmissionMap:re,thicknessMap:ie,gradientMap:Te,opaque:x.transparent===!1&&x.blending===No&&x.alphaToCoverage===!1,alphaMap:xe,alphaTest:we,alphaHash:Ye,combine:x.combine,mapUv:We&&p(x.map.channel),aoMapUv:xt&&p(x.aoMap.channel),lightMapUv:Rt&&p(x.lightMap.channel),bumpMapUv:Bt&&p(x.bumpMap.channel),normalMapUv:at&&p(x.normalMap.channel),displacementMapUv:Ct&&p(x.displacementMap.channel),emissiveMapUv:Ze&&p(x.emissiveMap.channel),metalnessMapUv:ft&&p(x.metalnessMap.channel),roughnessMapUv:pt&&p(x.roughnessMap.channel),anisotropyMapUv:Ke&&p(x.anisotropyMap.channel),clearcoatMapUv:R&&p(x.clearcoatMap.channel),clearcoatNormalMapUv:v&&p(x.clearcoatNormalMap.channel),clearcoatRoughnessMapUv:Y&&p(x.clearcoatRoughnessMap.channel),diffuseRoughnessMapUv:ue&&p(x.diffuseRoughnessMap.channel),iridescenceMapUv:oe&&p(x.iridescenceMap.channel),iridescenceThicknessMapUv:ve&&p(x.iridescenceThicknessMap.channel),sheenColorMapUv:Se&&p(x.sheenColorMap.channel),sheenRoughnessMapUv:ne&&p(x.sheenRoughnessMap.channel),specularMapUv:se&&p(x.specularMap.channel),specularColorMapUv:me&&p(x.specularColorMap.channel),specularIntensityMapUv:F&&p(x.specularIntensityMap.channel),transmissionMapUv:re&&p(x.transmissionMap.channel),thicknessMapUv:ie&&p(x.thicknessMap.channel),alphaMapUv:xe&&p(x.alphaMap.channel),vertexTangents:!!L.attributes.tangent&&(at||bt),vertexNormals:!!L.attributes.normal,vertexColors:x.vertexColors,vertexAlphas:x.vertexColors===!0&&!!L.attributes.color&&L.attributes.color.itemSize===4,pointsUvs:P.isPoints===!0&&!!L.attributes.uv&&(We||xe),fog:!!z,useFog:x.fog===!0,fogExp2:!!z&&z.isFogExp2,flatShading:x.wireframe===!1&&(x.flatShading===!0||L.attributes.normal===void 0&&at===!1&&(x.isMeshLambertMaterial||x.isMeshPhongMaterial||x.isMeshStandardMaterial||x.isMeshPhysicalMaterial)),sizeAttenuation:x.sizeAttenuation===!0,logarithmicDepthBuffer:f,reversedDepthBuffer:ye,skinning:P.isSkinnedMesh===!0,hasPositionAttribute:L.attributes.position!==void 0,morphTargets:L.morphAttributes.position!==void 0,morphNormals:L.morphAttributes.normal!==void 0,morphColors:L.morphAttributes.color!==void 0,morphTargetsCount:j,morphTextureStride:ae,numSunLights:T.sun.length,numDirLights:T.directional.length,numPointLights:T.point.length,numSpotLights:T.spot.length,numSpotLightMaps:T.spotLightMap.length,numRectAreaLights:T.rectArea.length,numHemiLights:T.hemi.length,numSunLightShadows:T.sunShadowMap.length,numDirLightShadows:T.directionalShadowMap.length,numPointLightShadows:T.pointShadowMap.length,numSpotLightShadows:T.spotShadowMap.length,numSpotLightShadowsWithMaps:T.numSpotLightShadowsWithMaps,numLightProbes:T.numLightProbes,numLightProbeGrids:B.filter(Ie=>Ie.texture!==null).length,numClippingPlanes:r.numPlanes,numClipIntersection:r.numIntersection,dithering:x.dithering,shadowMapEnabled:n.shadowMap.enabled&&k.length>0,shadowMapType:n.shadowMap.type,toneMapping:he,decodeVideoTexture:We&&x.map.isVideoTexture===!0&&At.getTransfer(x.map.colorSpace)===Ft,decodeVideoTextureEmissive:Ze&&x.emissiveMap.isVideoTexture===!0&&At.getTransfer(x.emissiveMap.colorSpace)===Ft,premultipliedAlpha:x.premultipliedAlpha,doubleSided:x.side===es,flipSided:x.side===$n,useDepthPacking:x.depthPacking>=0,depthPacking:x.depthPacking||0,index0AttributeName:x.index0AttributeName,extensionClipCullDistance:tt&&x.extensions.clipCullDistance===!0&&t.has("WEBGL_clip_cull_distance"),extensionMultiDraw:(tt&&x.extensions.multiDraw===!0||it)&&t.has("WEBGL_multi_draw"),rendererExtensionParallelShaderCompile:t.has("KHR_parallel_shader_compile"),customProgramCacheKey:x.customProgramCacheKey()};return nt.vertexUv1s=l.has(1),nt.vertexUv2s=l.has(2),nt.vertexUv3s=l.has(3),l.clear(),nt}function S(x){let T=[];if(x.shaderID?T.push(x.shaderID):(T.push(x.customVertexShaderID),T.push(x.customFragmentShaderID)),x.defines!==void 0)for(let k in x.defines)T.push(k),T.push(x.defines[k]);return x.isRawShaderMaterial===!1&&(d(T,x),m(T,x),T.push(n.outputColorSpace)),T.push(x.customProgramCacheKey),T.join()}function d(x,T){x.push(T.precision),x.push(T.outputColorSpace),x.push(T.envMapMode),x.push(T.envMapPMREM),x.push(T.envMapMaxLod),x.push(T.envMapSize),x.push(T.mapUv),x.push(T.alphaMapUv),x.push(T.lightMapUv),x.push(T.aoMapUv),x.push(T.bumpMapUv),x.push(T.normalMapUv),x.push(T.displacementMapUv),x.push(T.emissiveMapUv),x.push(T.metalnessMapUv),x.push(T.roughnessMapUv),x.push(T.anisotropyMapUv),x.push(T.clearcoatMapUv),x.push(T.clearcoatNormalMapUv),x.push(T.clearcoatRoughnessMapUv),x.push(T.diffuseRoughnessMapUv),x.push(T.iridescenceMapUv),x.push(T.iridescenceThicknessMapUv),x.push(T.sheenColorMapUv),x.push(T.sheenRoughnessMapUv),x.push(T.specularMapUv),x.push(T.specularColorMapUv),x.push(T.specularIntensityMapUv),x.push(T.transmissionMapUv),x.push(T.thicknessMapUv),x.push(T.combine),x.push(T.fogExp2),x.push(T.sizeAttenuation),x.push(T.morphTargetsCount),x.push(T.numSunLights),x.push(T.numDirLights),x.push(T.numPointLights),x.push(T.numSpotLights),x.push(T.numSpotLightMaps),x.push(T.numHemiLights),x.push(T.numRectAreaLights),x.push(T.numSunLightShadows),x.push(T.numDirLightShadows),x.push(T.numPointLightShadows),x.push(T.numSpotLightShadows),x.push(T.numSpotLightShadowsWithMaps),x.push(T.numLightProbes),x.push(T.numLightProbeGrids),x.push(T.shadowMapType),x.push(T.toneMapping),x.push(T.numClippingPlanes),x.push(T.numClipIntersection),x.push(T.depthPacking)}function m(x,T){o.disableAll(),T.instancing&&o.enable(0),T.instancingColor&&o.enable(1),T.instancingMorph&&o.enable(2),T.matcap&&o.enable(3),T.envMap&&o.enable(4),T.normalMapObjectSpace&&o.enable(5),T.normalMapTangentSpace&&o.enable(6),T.clearcoat&&o.enable(7),T.iridescence&&o.enable(8),T.alphaTest&&o.enable(9),T.vertexColors&&o.enable(10),T.vertexAlphas&&o.enable(11),T.vertexUv1s&&o.enable(12),T.vertexUv2s&&o.enable(13),T.vertexUv3s&&o.enable(14),T.vertexTangents&&o.enable(15),T.anisotropy&&o.enable(16),T.alphaHash&&o.enable(17),T.batching&&o.enable(18),T.dispersion&&o.enable(19),T.retroreflection&&o.enable(24),T.diffuseRoughness&&o.enable(25),T.batchingColor&&o.enable(20),T.gradientMap&&o.enable(21),T.packedNormalMap&&o.enable(22),T.vertexNormals&&o.enable(23),x.push(o.mask),o.disableAll(),T.fog&&o.enable(0),T.useFog&&o.enable(1),T.flatShading&&o.enable(2),T.logarithmicDepthBuffer&&o.enable(3),T.reversedDepthBuffer&&o.enable(4),T.skinning&&o.enable(5),T.morphTargets&&o.enable(6),T.morphNormals&&o.enable(7),T.morphColors&&o.enable(8),T.premultipliedAlpha&&o.enable(9),T.shadowMapEnabled&&o.enable(10),T.doubleSided&&o.enable(11),T.flipSided&&o.enable(12),T.useDepthPacking&&o.enable(13),T.dithering&&o.enable(14),T.transmission&&o.enable(15),T.sheen&&o.enable(16),T.opaque&&o.enable(17),T.pointsUvs&&o.enable(18),T.decodeVideoTexture&&o.enable(19),T.decodeVideoTextureEmissive&&o.enable(20),T.alphaToCoverage&&o.enable(21),T.numLightProbeGrids>0&&o.enable(22),T.hasPositionAttribute&&o.enable(23),x.push(o.mask)}function y(x){let T=u[x.type],k;if(T){let U=is[T];k=R0.clone(U.uniforms)}else k=x.uniforms;return k}function A(x,T){let k=h.get(T);return k!==void 0?++k.usedTimes:(k=new hE(n,T,x,s),c.push(k),h.set(T,k)),k}function b(x){if(--x.usedTimes===0){let T=c.indexOf(x);c[T]=c[c.length-1],c.pop(),h.delete(x.cacheKey),x.destroy()}}function C(x){a.remove(x)}function E(){a.dispose()}return{getParameters:g,getProgramCacheKey:S,getUniforms:y,acquireProgram:A,releaseProgram:b,releaseShaderCache:C,programs:c,dispose:E}}function pE(){let n=new WeakMap;function e(o){return n.has(o)}function t(o){let a=n.get(o);return a===void 0&&(a={},n.set(o,a)),a}function i(o){n.delete(o)}function s(o,a,l){n.get(o)[a]=l}function r(){n=new WeakMap}return{has:e,get:t,remove:i,update:s,dispose:r}}function mE(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.material.id!==e.material.id?n.material.id-e.material.id:n.materialVariant!==e.materialVariant?n.materialVariant-e.materialVariant:n.z!==e.z?n.z-e.z:n.id-e.id}function $0(n,e){return n.groupOrder!==e.groupOrder?n.groupOrder-e.groupOrder:n.renderOrder!==e.renderOrder?n.renderOrder-e.renderOrder:n.z!==e.z?e.z-n.z:n.id-e.id}function Z0(){let n=[],e=0,t=[],i=[],s=[];function r(){e=0,t.length=0,i.length=0,s.length=0}function o(u){let p=0;return u.isInstancedMesh&&(p+=2),u.isSkinnedMesh&&(p+=1),p}function a(u,p,g,S,d,m){let y=n[e];return y===void 0?(y={id:u.id,object:u,geometry:p,material:g,materialVariant:o(u),groupOrder:S,renderOrder:u.renderOrder,z:d,group:m},n[e]=y):(y.id=u.id,y.object=u,y.geometry=p,y.material=g,y.materialVariant=o(u),y.groupOrder=S,y.renderOrder=u.renderOrder,y.z=d,y.group=m),e++,y}function l(u,p,g,S,d,m,y){y.reversedDepth===!0&&(d=-d);let A=a(u,p,g,S,d,m);g.transmission>0?i.push(A):g.transparent===!0?s.push(A):t.push(A)}function c(u,p,g,S,d,m){let y=a(u,p,g,S,d,m);g.transmission>0?i.unshift(y):g.transparent===!0?s.unshift(y):t.unshift(y)}function h(u,p){t.length>1&&t.sort(u||mE),i.length>1&&i.sort(p||$0),s.length>1&&s.sort(p||$0)}function f(){for(let u=e,p=n.length;u<p;u++){let g=n[u];if(g.id===null)break;g.id=null,g.object=null,g.geometry=null,g.material=null,g.group=null}}return{opaque:t,transmissive:i,transparent:s,init:r,push:l,unshift:c,finish:f,sort:h}}function gE(){let n=new WeakMap;function e(i,s){let r=n.get(i),o;return r===void 0?(o=new Z0,n.set(i,[o])):s>=r.length?(o=new Z0,r.push(o)):o=r[s],o}function t(){n=new WeakMap}return{get:e,dispose:t}}function _E(){let n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={direction:new K,color:new gt};break;case"SpotLight":t={position:new K,direction:new K,color:new gt,distance:0,coneCos:0,penumbraCos:0,decay:0};break;case"PointLight":t={position:new K,color:new gt,distance:0,decay:0};break;case"HemisphereLight":t={direction:new K,skyColor:new gt,groundColor:new gt};break;case"RectAreaLight":t={color:new gt,position:new K,halfWidth:new K,halfHeight:new K};break}return n[e.id]=t,t}}}function xE(){let n={};return{get:function(e){if(n[e.id]!==void 0)return n[e.id];let t;switch(e.type){case"SunLight":case"DirectionalLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new ut};break;case"SpotLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new ut};break;case"PointLight":t={shadowIntensity:1,shadowBias:0,shadowNormalBias:0,shadowRadius:1,shadowMapSize:new ut,shadowCameraNear:1,shadowCameraFar:1e3};break}return n[e.id]=t,t}}}var yE=0;function vE(n,e){return(e.castShadow?2:0)-(n.castShadow?2:0)+(e.map?1:0)-(n.map?1:0)}function SE(n){let e=new _E,t=xE(),i={version:0,hash:{sunLength:-1,directionalLength:-1,pointLength:-1,spotLength:-1,rectAreaLength:-1,hemiLength:-1,numSunShadows:-1,numDirectionalShadows:-1,numPointShadows:-1,numSpotShadows:-1,numSpotMaps:-1,numLightProbes:-1},ambient:[0,0,0],probe:[],sun:[],sunShadow:[],sunShadowMap:[],sunShadowMatrix:[],sunShadowCascade:[],directional:[],directionalShadow:[],directionalShadowMap:[],directionalShadowMatrix:[],spot:[],spotLightMap:[],spotShadow:[],spotShadowMap:[],spotLightMatrix:[],rectArea:[],rectAreaLTC1:null,rectAreaLTC2:null,point:[],pointShadow:[],pointShadowMap:[],pointShadowMatrix:[],hemi:[],numSpotLightShadowsWithMaps:0,numLightProbes:0};for(let c=0;c<9;c++)i.probe.push(new K);let s=new K,r=new en,o=new en;function a(c){let h=0,f=0,u=0;for(let B=0;B<9;B++)i.probe[B].set(0,0,0);let p=0,g=0,S=0,d=0,m=0,y=0,A=0,b=0,C=0,E=0,x=0,T=0,k=0,U=0;c.sort(vE);for(let B=0,z=c.length;B<z;B++){let L=c[B],H=L.color,W=L.intensity,D=L.distance,te=null;if(L.shadow&&L.shadow.map&&(L.shadow.map.texture.format===or?te=L.shadow.map.texture:te=L.shadow.map.depthTexture||L.shadow.map.texture),L.isAmbientLight)h+=H.r*W,f+=H.g*W,u+=H.b*W;else if(L.isLightProbe){for(let X=0;X<9;X++)i.probe[X].addScaledVector(L.sh.coefficients[X],W);U++}else if(L.isSunLight){let X=e.get(L);if(X.color.copy(L.color).multiplyScalar(L.intensity),L.castShadow){let q=L.shadow,j=t.get(L);j.shadowIntensity=q.intensity,j.shadowBias=q.bias,j.shadowNormalBias=q.normalBias,j.shadowRadius=q.radius,j.shadowMapSize.copy(q.mapSize).multiply(q.getFrameExtents()),i.sunShadow[g]=j,i.sunShadowMap[g]=te;let ae=q.getViewportCount();for(let ce=0;ce<ae;ce++)i.sunShadowMatrix[S+ce]=q.getMatrix(ce),i.sunShadowCascade[S+ce]=q._cascadeData[ce];S+=ae,g++}i.sun[p]=X,p++}else if(L.isDirectionalLight){let X=e.get(L);if(X.color.copy(L.color).multiplyScalar(L.intensity),L.castShadow){let q=L.shadow,j=t.get(L);j.shadowIntensity=q.intensity,j.shadowBias=q.bias,j.shadowNormalBias=q.normalBias,j.shadowRadius=q.radius,j.shadowMapSize=q.mapSize,i.directionalShadow[d]=j,i.directionalShadowMap[d]=te,i.directionalShadowMatrix[d]=L.shadow.matrix,C++}i.directional[d]=X,d++}else if(L.isSpotLight){let X=e.get(L);X.position.setFromMatrixPosition(L.matrixWorld),X.color.copy(H).multiplyScalar(W),X.distance=D,X.coneCos=Math.cos(L.angle),X.penumbraCos=Math.cos(L.angle*(1-L.penumbra)),X.decay=L.decay,i.spot[y]=X;let q=L.shadow;if(L.map&&(i.spotLightMap[T]=L.map,T++,q.updateMatrices(L),L.castShadow&&k++),i.spotLightMatrix[y]=q.matrix,L.castShadow){let j=t.get(L);j.shadowIntensity=q.intensity,j.shadowBias=q.bias,j.shadowNormalBias=q.normalBias,j.shadowRadius=q.radius,j.shadowMapSize=q.mapSize,i.spotShadow[y]=j,i.spotShadowMap[y]=te,x++}y++}else if(L.isRectAreaLight){let X=e.get(L);X.color.copy(H).multiplyScalar(W),X.halfWidth.set(L.width*.5,0,0),X.halfHeight.set(0,L.height*.5,0),i.rectArea[A]=X,A++}else if(L.isPointLight){let X=e.get(L);if(X.color.copy(L.color).multiplyScalar(L.intensity),X.distance=L.distance,X.decay=L.decay,L.castShadow){let q=L.shadow,j=t.get(L);j.shadowIntensity=q.intensity,j.shadowBias=q.bias,j.shadowNormalBias=q.normalBias,j.shadowRadius=q.radius,j.shadowMapSize=q.mapSize,j.shadowCameraNear=q.camera.near,j.shadowCameraFar=q.camera.far,i.pointShadow[m]=j,i.pointShadowMap[m]=te,i.pointShadowMatrix[m]=L.shadow.matrix,E++}i.point[m]=X,m++}else if(L.isHemisphereLight){let X=e.get(L);X.skyColor.copy(L.color).multiplyScalar(W),X.groundColor.copy(L.groundColor).multiplyScalar(W),i.hemi[b]=X,b++}}A>0&&(n.has("OES_texture_float_linear")===!0?(i.rectAreaLTC1=Ue.LTC_FLOAT_1,i.rectAreaLTC2=Ue.LTC_FLOAT_2):(i.rectAreaLTC1=Ue.LTC_HALF_1,i.rectAreaLTC2=Ue.LTC_HALF_2)),i.ambient[0]=h,i.ambient[1]=f,i.ambient[2]=u;let P=i.hash;(P.sunLength!==p||P.directionalLength!==d||P.pointLength!==m||P.spotLength!==y||P.rectAreaLength!==A||P.hemiLength!==b||P.numSunShadows!==g||P.numDirectionalShadows!==C||P.numPointShadows!==E||P.numSpotShadows!==x||P.numSpotMaps!==T||P.numLightProbes!==U)&&(i.sun.length=p,i.directional.length=d,i.spot.length=y,i.rectArea.length=A,i.point.length=m,i.hemi.length=b,i.sunShadow.length=g,i.sunShadowMap.length=g,i.sunShadowMatrix.length=S,i.sunShadowCascade.length=S,i.directionalShadow.length=C,i.directionalShadowMap.length=C,i.directionalShadowMatrix.length=C,i.pointShadow.length=E,i.pointShadowMap.length=E,i.pointShadowMatrix.length=E,i.spotShadow.length=x,i.spotShadowMap.length=x,i.spotLightMatrix.length=x+T-k,i.spotLightMap.length=T,i.numSpotLightShadowsWithMaps=k,i.numLightProbes=U,P.sunLength=p,P.directionalLength=d,P.pointLength=m,P.spotLength=y,P.rectAreaLength=A,P.hemiLength=b,P.numSunShadows=g,P.numDirectionalShadows=C,P.numPointShadows=E,P.numSpotShadows=x,P.numSpotMaps=T,P.numLightProbes=U,i.version=yE++)}function l(c,h){let f=0,u=0,p=0,g=0,S=0,d=0,m=h.matrixWorldInverse;for(let y=0,A=c.length;y<A;y++){let b=c[y];if(b.isSunLight){let C=i.sun[f];C.direction.setFromMatrixPosition(b.matrixWorld),C.direction.transformDirection(m),f++}else if(b.isDirectionalLight){let C=i.directional[u];C.direction.setFromMatrixPosition(b.matrixWorld),s.setFromMatrixPosition(b.target.matrixWorld),C.direction.sub(s),C.direction.transformDirection(m),u++}else if(b.isSpotLight){let C=i.spot[g];C.position.setFromMatrixPosition(b.matrixWorld),C.position.applyMatrix4(m),C.direction.setFromMatrixPosition(b.matrixWorld),s.setFromMatrixPosition(b.target.matrixWorld),C.direction.sub(s),C.direction.transformDirection(m),g++}else if(b.isRectAreaLight){let C=i.rectArea[S];C.position.setFromMatrixPosition(b.matrixWorld),C.position.applyMatrix4(m),o.identity(),r.copy(b.matrixWorld),r.premultiply(m),o.extractRotation(r),C.halfWidth.set(b.width*.5,0,0),C.halfHeight.set(0,b.height*.5,0),C.halfWidth.applyMatrix4(o),C.halfHeight.applyMatrix4(o),S++}else if(b.isPointLight){let C=i.point[p];C.position.setFromMatrixPosition(b.matrixWorld),C.position.applyMatrix4(m),p++}else if(b.isHemisphereLight){let C=i.hemi[d];C.direction.setFromMatrixPosition(b.matrixWorld),C.direction.transformDirection(m),d++}}}return{setup:a,setupView:l,state:i}}function K0(n){let e=new SE(n),t=[],i=[],s=[];function r(f){h.camera=f,t.length=0,i.length=0,s.length=0}function o(f){f.isLightProbeGrid?s.push(f):t.push(f)}function a(f){i.push(f)}function l(){e.setup(t),s.sort((f,u)=>f.priority-u.priority||f.id-u.id)}function c(f){e.setupView(t,f)}let h={lightsArray:t,shadowsArray:i,lightProbeGridArray:s,camera:null,lights:e,transmissionRenderTarget:{},textureUnits:0};return{init:r,state:h,setupLights:l,setupLightsView:c,pushLight:o,pushShadow:a}}function bE(n){let e=new WeakMap;function t(s,r=0){let o=e.get(s),a;return o===void 0?(a=new K0(n),e.set(s,[a])):r>=o.length?(a=new K0(n),o.push(a)):a=o[r],a}function i(){e=new WeakMap}return{get:t,dispose:i}}var ME=`void main() {
	gl_Position = vec4( position, 1.0 );
}`,wE=`uniform sampler2D shadow_pass;
uniform vec2 resolution;
uniform float radius;
void main() {
	const float samples = float( VSM_SAMPLES );
	float mean = 0.0;
	float squared_mean = 0.0;
	float uvStride = samples <= 1.0 ? 0.0 : 2.0 / ( samples - 1.0 );
	float uvStart = samples <= 1.0 ? 0.0 : - 1.0;
	for ( float i = 0.0; i < samples; i ++ ) {
		float uvOffset = uvStart + i * uvStride;
		#ifdef HORIZONTAL_PASS
			vec2 distribution = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( uvOffset, 0.0 ) * radius ) / resolution ).rg;
			mean += distribution.x;
			squared_mean += distribution.y * distribution.y + distribution.x * distribution.x;
		#else
			float depth = texture2D( shadow_pass, ( gl_FragCoord.xy + vec2( 0.0, uvOffset ) * radius ) / resolution ).r;
			mean += depth;
			squared_mean += depth * depth;
		#endif
	}
	mean = mean / samples;
	squared_mean = squared_mean / samples;
	float std_dev = sqrt( max( 0.0, squared_mean - mean * mean ) );
	gl_FragColor = vec4( mean, std_dev, 0.0, 1.0 );
}`,EE=[new K(1,0,0),new K(-1,0,0),new K(0,1,0),new K(0,-1,0),new K(0,0,1),new K(0,0,-1)],TE=[new K(0,-1,0),new K(0,-1,0),new K(0,0,1),new K(0,0,-1),new K(0,-1,0),new K(0,-1,0)],J0=new en,Ka=new K,_d=new K;function AE(n,e,t){let i=new Ar,s=new ut,r=new ut,o=new sn,a=new Dc,l=new Uc,c={},h=t.maxTextureSize,f={[rr]:$n,[$n]:rr,[es]:es},u=new Qi({defines:{VSM_SAMPLES:8},uniforms:{shadow_pass:{value:null},resolution:{value:new ut},radius:{value:4}},vertexShader:ME,fragmentShader:wE}),p=u.clone();p.defines.HORIZONTAL_PASS=1;let g=new jn;g.setAttribute("position",new fi(new Float32Array([-1,-1,.5,3,-1,.5,-1,3,.5]),3));let S=new ji(g,u),d=this;this.enabled=!1,this.autoUpdate=!0,this.needsUpdate=!1,this.type=Ha;let m=this.type;this.render=function(E,x,T){if(d.enabled===!1||d.autoUpdate===!1&&d.needsUpdate===!1||E.length===0)return;this.type===Wg&&(Je("WebGLShadowMap: PCFSoftShadowMap has been removed. Using PCFShadowMap instead."),this.type=Ha);let k=n.getRenderTarget(),U=n.getActiveCubeFace(),P=n.getActiveMipmapLevel(),B=n.state;B.setBlending(Rr),B.buffers.depth.getReversed()===!0?B.buffers.color.setClear(0,0,0,0):B.buffers.color.setClear(1,1,1,1),B.buffers.depth.setTest(!0),B.setScissorTest(!1);let z=m!==this.type;z&&x.traverse(function(L){L.material&&(Array.isArray(L.material)?L.material.forEach(H=>H.needsUpdate=!0):L.material.needsUpdate=!0)});for(let L=0,H=E.length;L<H;L++){let W=E[L],D=W.shadow;if(D===void 0){Je("WebGLShadowMap:",W,"has no shadow.");continue}if(D.autoUpdate===!1&&D.needsUpdate===!1)continue;s.copy(D.mapSize);let te=D.getFrameExtents();s.multiply(te),r.copy(D.mapSize),(s.x>h||s.y>h)&&(s.x>h&&(r.x=Math.floor(h/te.x),s.x=r.x*te.x,D.mapSize.x=r.x),s.y>h&&(r.y=Math.floor(h/te.y),s.y=r.y*te.y,D.mapSize.y=r.y));let X=n.state.buffers.depth.getReversed();if(D.camera._reversedDepth=X,D.map===null||z===!0){if(D.map!==null&&(D.map.depthTexture!==null&&(D.map.depthTexture.dispose(),D.map.depthTexture=null),D.map.dispose()),this.type===Lo){if(W.isPointLight){Je("WebGLShadowMap: VSM shadow maps are not supported for PointLights. Use PCF or BasicShadowMap instead.");continue}D.map=new pi(s.x,s.y,{format:or,type:Fi,minFilter:Yn,magFilter:Yn,generateMipmaps:!1}),D.map.texture.name=W.name+".shadowMap",D.map.depthTexture=new Ms(s.x,s.y,Oi),D.map.depthTexture.name=W.name+".shadowMapDepth",D.map.depthTexture.format=Ss,D.map.depthTexture.compareFunction=null,D.map.depthTexture.minFilter=Ln,D.map.depthTexture.magFilter=Ln}else W.isPointLight?(D.map=new ja(s.x),D.map.depthTexture=new Da(s.x,Ui)):(D.map=new pi(s.x,s.y),D.map.depthTexture=new Ms(s.x,s.y,Ui)),D.map.depthTexture.name=W.name+".shadowMap",D.map.depthTexture.format=Ss,this.type===Ha?(D.map.depthTexture.compareFunction=X?Qf:jf,D.map.depthTexture.minFilter=Yn,D.map.depthTexture.magFilter=Yn):(D.map.depthTexture.compareFunction=null,D.map.depthTexture.minFilter=Ln,D.map.depthTexture.magFilter=Ln);D.camera.updateProjectionMatrix()}D.map.isWebGLCubeRenderTarget!==!0&&(D.map.width!==s.x||D.map.height!==s.y)&&D.map.setSize(s.x,s.y);let q=D.map.isWebGLCubeRenderTarget?6:D.getViewportCount();W.isPointLight!==!0&&D.updateMatrices(W,T);let j=(D.camera.layers.mask&4294967294)!==0?D.camera.layers:T.layers;for(let ae=0;ae<q;ae++){let ce=D.getCamera(ae);if(W.isPointLight){let ee=D.camera,pe=D.matrix,fe=W.distance||ee.far;fe!==ee.far&&(ee.far=fe,ee.updateProjectionMatrix()),Ka.setFromMatrixPosition(W.matrixWorld),ee.position.copy(Ka),_d.copy(ee.position),_d.add(EE[ae]),ee.up.copy(TE[ae]),ee.lookAt(_d),ee.updateMatrixWorld(),pe.makeTranslation(-Ka.x,-Ka.y,-Ka.z),J0.multiplyMatrices(ee.projectionMatrix,ee.matrixWorldInverse),D._frustum.setFromProjectionMatrix(J0,ee.coordinateSystem,ee.reversedDepth)}if(D.map.isWebGLCubeRenderTarget)n.setRenderTarget(D.map,ae),n.clear();else{ae===0&&(n.setRenderTarget(D.map),n.clear());let ee=D.getViewport(ae);o.set(r.x*ee.x,r.y*ee.y,r.x*ee.z,r.y*ee.w),B.viewport(o)}i=D.getFrustum(ae),b(x,T,ce,W,j,this.type)}D.isPointLightShadow!==!0&&this.type===Lo&&y(D,T),D.needsUpdate=!1}m=this.type,d.needsUpdate=!1,n.setRenderTarget(k,U,P)};function y(E,x){let T=e.update(S);u.defines.VSM_SAMPLES!==E.blurSamples&&(u.defines.VSM_SAMPLES=E.blurSamples,p.defines.VSM_SAMPLES=E.blurSamples,u.needsUpdate=!0,p.needsUpdate=!0),E.mapPass===null?E.mapPass=new pi(s.x,s.y,{format:or,type:Fi}):(E.mapPass.width!==E.map.width||E.mapPass.height!==E.map.height)&&E.mapPass.setSize(E.map.width,E.map.height),u.uniforms.shadow_pass.value=E.map.depthTexture,u.uniforms.resolution.value.set(E.map.width,E.map.height),u.uniforms.radius.value=E.radius,n.setRenderTarget(E.mapPass),n.clear(),n.renderBufferDirect(x,null,T,u,S,null),p.uniforms.shadow_pass.value=E.mapPass.texture,p.uniforms.resolution.value.set(E.map.width,E.map.height),p.uniforms.radius.value=E.radius,n.setRenderTarget(E.map),n.clear(),n.renderBufferDirect(x,null,T,p,S,null)}function A(E,x,T,k){let U=null,P=T.isPointLight===!0?E.customDistanceMaterial:E.customDepthMaterial;if(P!==void 0)U=P;else if(U=T.isPointLight===!0?l:a,n.localClippingEnabled&&x.clipShadows===!0&&Array.isArray(x.clippingPlanes)&&x.clippingPlanes.length!==0||x.displacementMap&&x.displacementScale!==0||x.alphaMap&&x.alphaTest>0||x.map&&x.alphaTest>0||x.alphaToCoverage===!0){let B=U.uuid,z=x.uuid,L=c[B];L===void 0&&(L={},c[B]=L);let H=L[z];H===void 0&&(H=U.clone(),L[z]=H,x.addEventListener("dispose",C)),U=H}if(U.visible=x.visible,U.wireframe=x.wireframe,k===Lo?U.side=x.shadowSide!==null?x.shadowSide:x.side:U.side=x.shadowSide!==null?x.shadowSide:f[x.side],U.alphaMap=x.alphaMap,U.alphaTest=x.alphaToCoverage===!0?.5:x.alphaTest,U.map=x.map,U.clipShadows=x.clipShadows,U.clippingPlanes=x.clippingPlanes,U.clipIntersection=x.clipIntersection,U.displacementMap=x.displacementMap,U.displacementScale=x.displacementScale,U.displacementBias=x.displacementBias,U.wireframeLinewidth=x.wireframeLinewidth,U.linewidth=x.linewidth,T.isPointLight===!0&&U.isMeshDistanceMaterial===!0){let B=n.properties.get(U);B.light=T}return U}function b(E,x,T,k,U,P){if(E.visible===!1)return;if(E.layers.test(U)&&(E.isMesh||E.isLine||E.isPoints)&&(E.castShadow||E.receiveShadow&&P===Lo)&&(!E.frustumCulled||E.intersectsFrustum(i))){E.modelViewMatrix.multiplyMatrices(T.matrixWorldInverse,E.matrixWorld);let L=e.update(E),H=E.material;if(Array.isArray(H)){let W=L.groups;for(let D=0,te=W.length;D<te;D++){let X=W[D],q=H[X.materialIndex];if(q&&q.visible){let j=A(E,q,k,P);E.onBeforeShadow(n,E,x,T,L,j,X),n.renderBufferDirect(T,null,L,j,E,X),E.onAfterShadow(n,E,x,T,L,j,X)}}}else if(H.visible){let W=A(E,H,k,P);E.onBeforeShadow(n,E,x,T,L,W,null),n.renderBufferDirect(T,null,L,W,E,null),E.onAfterShadow(n,E,x,T,L,W,null)}}let z=E.children;for(let L=0,H=z.length;L<H;L++)b(z[L],x,T,k,U,P)}function C(E){E.target.removeEventListener("dispose",C);for(let T in c){let k=c[T],U=E.target.uuid;U in k&&(k[U].dispose(),delete k[U])}}}function RE(n,e){function t(){let F=!1,re=new sn,ie=null,Te=new sn(0,0,0,0);return{setMask:function(xe){ie!==xe&&!F&&(n.colorMask(xe,xe,xe,xe),ie=xe)},setLocked:function(xe){F=xe},setClear:function(xe,we,Ye,tt,he){he===!0&&(xe*=tt,we*=tt,Ye*=tt),re.set(xe,we,Ye,tt),Te.equals(re)===!1&&(n.clearColor(xe,we,Ye,tt),Te.copy(re))},reset:function(){F=!1,ie=null,Te.set(-1,0,0,0)}}}function i(){let F=!1,re=!1,ie=null,Te=null,xe=null;return{setReversed:function(we){if(re!==we){let Ye=e.get("EXT_clip_control");we?Ye.clipControlEXT(Ye.LOWER_LEFT_EXT,Ye.ZERO_TO_ONE_EXT):Ye.clipControlEXT(Ye.LOWER_LEFT_EXT,Ye.NEGATIVE_ONE_TO_ONE_EXT),re=we;let tt=xe;xe=null,this.setClear(tt)}},getReversed:function(){return re},setTest:function(we){we?ye(n.DEPTH_TEST):qe(n.DEPTH_TEST)},setMask:function(we){ie!==we&&!F&&(n.depthMask(we),ie=we)},setFunc:function(we){if(re&&(we=w0[we]),Te!==we){switch(we){case pc:n.depthFunc(n.NEVER);break;case mc:n.depthFunc(n.ALWAYS);break;case gc:n.depthFunc(n.LESS);break;case bo:n.depthFunc(n.LEQUAL);break;case _c:n.depthFunc(n.EQUAL);break;case xc:n.depthFunc(n.GEQUAL);break;case yc:n.depthFunc(n.GREATER);break;case vc:n.depthFunc(n.NOTEQUAL);break;default:n.depthFunc(n.LEQUAL)}Te=we}},setLocked:function(we){F=we},setClear:function(we){xe!==we&&(xe=we,re&&(we=1-we),n.clearDepth(we))},reset:function(){F=!1,ie=null,Te=null,xe=null,re=!1}}}function s(){let F=!1,re=null,ie=null,Te=null,xe=null,we=null,Ye=null,tt=null,he=null;return{setTest:function(Ge){F||(Ge?ye(n.STENCIL_TEST):qe(n.STENCIL_TEST))},setMask:function(Ge){re!==Ge&&!F&&(n.stencilMask(Ge),re=Ge)},setFunc:function(Ge,nt,Ie){(ie!==Ge||Te!==nt||xe!==Ie)&&(n.stencilFunc(Ge,nt,Ie),ie=Ge,Te=nt,xe=Ie)},setOp:function(Ge,nt,Ie){(we!==Ge||Ye!==nt||tt!==Ie)&&(n.stencilOp(Ge,nt,Ie),we=Ge,Ye=nt,tt=Ie)},setLocked:function(Ge){F=Ge},setClear:function(Ge){he!==Ge&&(n.clearStencil(Ge),he=Ge)},reset:function(){F=!1,re=null,ie=null,Te=null,xe=null,we=null,Ye=null,tt=null,he=null}}}let r=new t,o=new i,a=new s,l={},c=new WeakMap,h={},f={},u={},p=new WeakMap,g=[],S=null,d=!1,m=null,y=null,A=null,b=null,C=null,E=null,x=null,T=new gt(0,0,0),k=0,U=!1,P=null,B=null,z=null,L=null,H=null,W=n.getParameter(n.MAX_COMBINED_TEXTURE_IMAGE_UNITS),D=!1,te=0,X=n.getParameter(n.VERSION);X.indexOf("WebGL")!==-1?(te=parseFloat(/^WebGL (\d)/.exec(X)[1]),D=te>=1):X.indexOf("OpenGL ES")!==-1&&(te=parseFloat(/^OpenGL ES (\d)/.exec(X)[1]),D=te>=2);let q=null,j={},ae=n.getParameter(n.SCISSOR_BOX),ce=n.getParameter(n.VIEWPORT),ee=new sn().fromArray(ae),pe=new sn().fromArray(ce);function fe(F,re,ie,Te){let xe=new Uint8Array(4),we=n.createTexture();n.bindTexture(F,we),n.texParameteri(F,n.TEXTURE_MIN_FILTER,n.NEAREST),n.texParameteri(F,n.TEXTURE_MAG_FILTER,n.NEAREST);for(let Ye=0;Ye<ie;Ye++)F===n.TEXTURE_3D||F===n.TEXTURE_2D_ARRAY?n.texImage3D(re,0,n.RGBA,1,1,Te,0,n.RGBA,n.UNSIGNED_BYTE,xe):n.texImage2D(re+Ye,0,n.RGBA,1,1,0,n.RGBA,n.UNSIGNED_BYTE,xe);return we}let Me={};Me[n.TEXTURE_2D]=fe(n.TEXTURE_2D,n.TEXTURE_2D,1),Me[n.TEXTURE_CUBE_MAP]=fe(n.TEXTURE_CUBE_MAP,n.TEXTURE_CUBE_MAP_POSITIVE_X,6),Me[n.TEXTURE_2D_ARRAY]=fe(n.TEXTURE_2D_ARRAY,n.TEXTURE_2D_ARRAY,1,1),Me[n.TEXTURE_3D]=fe(n.TEXTURE_3D,n.TEXTURE_3D,1,1),r.setClear(0,0,0,1),o.setClear(1),a.setClear(0),ye(n.DEPTH_TEST),o.setFunc(bo),Bt(!1),at(Cf),ye(n.CULL_FACE),xt(Rr);function ye(F){h[F]!==!0&&(n.enable(F),h[F]=!0)}function qe(F){h[F]!==!1&&(n.disable(F),h[F]=!1)}function it(F,re){return u[F]!==re?(n.bindFramebuffer(F,re),u[F]=re,F===n.DRAW_FRAMEBUFFER&&(u[n.FRAMEBUFFER]=re),F===n.FRAMEBUFFER&&(u[n.DRAW_FRAMEBUFFER]=re),!0):!1}function We(F,re){let ie=g,Te=!1;if(F){ie=p.get(re),ie===void 0&&(ie=[],p.set(re,ie));let xe=F.textures;if(ie.length!==xe.length||ie[0]!==n.COLOR_ATTACHMENT0){for(let we=0,Ye=xe.length;we<Ye;we++)ie[we]=n.COLOR_ATTACHMENT0+we;ie.length=xe.length,Te=!0}}else ie[0]!==n.BACK&&(ie[0]=n.BACK,Te=!0);Te&&n.drawBuffers(ie)}function Ce(F){return S!==F?(n.useProgram(F),S=F,!0):!1}let Ne={[Cr]:n.FUNC_ADD,[qg]:n.FUNC_SUBTRACT,[Yg]:n.FUNC_REVERSE_SUBTRACT};Ne[$g]=n.MIN,Ne[Zg]=n.MAX;let Be={[Kg]:n.ZERO,[Jg]:n.ONE,[jg]:n.SRC_COLOR,[Nf]:n.SRC_ALPHA,[s0]:n.SRC_ALPHA_SATURATE,[n0]:n.DST_COLOR,[e0]:n.DST_ALPHA,[Qg]:n.ONE_MINUS_SRC_COLOR,[Df]:n.ONE_MINUS_SRC_ALPHA,[i0]:n.ONE_MINUS_DST_COLOR,[t0]:n.ONE_MINUS_DST_ALPHA,[r0]:n.CONSTANT_COLOR,[o0]:n.ONE_MINUS_CONSTANT_COLOR,[a0]:n.CONSTANT_ALPHA,[l0]:n.ONE_MINUS_CONSTANT_ALPHA};function xt(F,re,ie,Te,xe,we,Ye,tt,he,Ge){if(F===Rr){d===!0&&(qe(n.BLEND),d=!1);return}if(d===!1&&(ye(n.BLEND),d=!0),F!==Xg){if(F!==m||Ge!==U){if((y!==Cr||C!==Cr)&&(n.blendEquation(n.FUNC_ADD),y=Cr,C=Cr),Ge)switch(F){case No:n.blendFuncSeparate(n.ONE,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case If:n.blendFunc(n.ONE,n.ONE);break;case Pf:n.blendFuncSeparate(n.ZERO,n.ONE_MINUS_SRC_COLOR,n.ZERO,n.ONE);break;case Lf:n.blendFuncSeparate(n.DST_COLOR,n.ONE_MINUS_SRC_ALPHA,n.ZERO,n.ONE);break;default:rt("WebGLState: Invalid blending: ",F);break}else switch(F){case No:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE_MINUS_SRC_ALPHA,n.ONE,n.ONE_MINUS_SRC_ALPHA);break;case If:n.blendFuncSeparate(n.SRC_ALPHA,n.ONE,n.ONE,n.ONE);break;case Pf:rt("WebGLState: SubtractiveBlending requires material.premultipliedAlpha = true");break;case Lf:rt("WebGLState: MultiplyBlending requires material.premultipliedAlpha = true");break;default:rt("WebGLState: Invalid blending: ",F);break}A=null,b=null,E=null,x=null,T.set(0,0,0),k=0,m=F,U=Ge}return}xe=xe||re,we=we||ie,Ye=Ye||Te,(re!==y||xe!==C)&&(n.blendEquationSeparate(Ne[re],Ne[xe]),y=re,C=xe),(ie!==A||Te!==b||we!==E||Ye!==x)&&(n.blendFuncSeparate(Be[ie],Be[Te],Be[we],Be[Ye]),A=ie,b=Te,E=we,x=Ye),(tt.equals(T)===!1||he!==k)&&(n.blendColor(tt.r,tt.g,tt.b,he),T.copy(tt),k=he),m=F,U=!1}function Rt(F,re){F.side===es?qe(n.CULL_FACE):ye(n.CULL_FACE);let ie=F.side===$n;re&&(ie=!ie),Bt(ie),F.blending===No&&F.transparent===!1?xt(Rr):xt(F.blending,F.blendEquation,F.blendSrc,F.blendDst,F.blendEquationAlpha,F.blendSrcAlpha,F.blendDstAlpha,F.blendColor,F.blendAlpha,F.premultipliedAlpha),o.setFunc(F.depthFunc),o.setTest(F.depthTest),o.setMask(F.depthWrite),r.setMask(F.colorWrite);let Te=F.stencilWrite;a.setTest(Te),Te&&(a.setMask(F.stencilWriteMask),a.setFunc(F.stencilFunc,F.stencilRef,F.stencilFuncMask),a.setOp(F.stencilFail,F.stencilZFail,F.stencilZPass)),Ze(F.polygonOffset,F.polygonOffsetFactor,F.polygonOffsetUnits),F.alphaToCoverage===!0?ye(n.SAMPLE_ALPHA_TO_COVERAGE):qe(n.SAMPLE_ALPHA_TO_COVERAGE)}function Bt(F){P!==F&&(F?n.frontFace(n.CW):n.frontFace(n.CCW),P=F)}function at(F){F!==Hg?(ye(n.CULL_FACE),F!==B&&(F===Cf?n.cullFace(n.BACK):F===Vg?n.cullFace(n.FRONT):n.cullFace(n.FRONT_AND_BACK))):qe(n.CULL_FACE),B=F}function Ct(F){F!==z&&(D&&n.lineWidth(F),z=F)}function Ze(F,re,ie){F?(ye(n.POLYGON_OFFSET_FILL),(L!==re||H!==ie)&&(L=re,H=ie,o.getReversed()&&(re=-re,ie=-ie),n.polygonOffset(re,ie))):qe(n.POLYGON_OFFSET_FILL)}function ft(F){F?ye(n.SCISSOR_TEST):qe(n.SCISSOR_TEST)}function pt(F){F===void 0&&(F=n.TEXTURE0+W-1),q!==F&&(n.activeTexture(F),q=F)}function bt(F,re,ie){ie===void 0&&(q===null?ie=n.TEXTURE0+W-1:ie=q);let Te=j[ie];Te===void 0&&(Te={type:void 0,texture:void 0},j[ie]=Te),(Te.type!==F||Te.texture!==re)&&(q!==ie&&(n.activeTexture(ie),q=ie),n.bindTexture(F,re||Me[F]),Te.type=F,Te.texture=re)}function O(){let F=j[q];F!==void 0&&F.type!==void 0&&(n.bindTexture(F.type,null),F.type=void 0,F.texture=void 0)}function Pe(){try{n.compressedTexImage2D(...arguments)}catch(F){rt("WebGLState:",F)}}function je(){try{n.compressedTexImage3D(...arguments)}catch(F){rt("WebGLState:",F)}}function ht(){try{n.texSubImage2D(...arguments)}catch(F){rt("WebGLState:",F)}}function Ee(){try{n.texSubImage3D(...arguments)}catch(F){rt("WebGLState:",F)}}function Vt(){try{n.compressedTexSubImage2D(...arguments)}catch(F){rt("WebGLState:",F)}}function Xe(){try{n.compressedTexSubImage3D(...arguments)}catch(F){rt("WebGLState:",F)}}function Ke(){try{n.texStorage2D(...arguments)}catch(F){rt("WebGLState:",F)}}function R(){try{n.texStorage3D(...arguments)}catch(F){rt("WebGLState:",F)}}function v(){try{n.texImage2D(...arguments)}catch(F){rt("WebGLState:",F)}}function Y(){try{n.texImage3D(...arguments)}catch(F){rt("WebGLState:",F)}}function ue(F){return f[F]!==void 0?f[F]:n.getParameter(F)}function oe(F,re){f[F]!==re&&(n.pixelStorei(F,re),f[F]=re)}function ve(F){ee.equals(F)===!1&&(n.scissor(F.x,F.y,F.z,F.w),ee.copy(F))}function Se(F){pe.equals(F)===!1&&(n.viewport(F.x,F.y,F.z,F.w),pe.copy(F))}function ne(F,re){let ie=c.get(re);ie===void 0&&(ie=new WeakMap,c.set(re,ie));let Te=ie.get(F);Te===void 0&&(Te=n.getUniformBlockIndex(re,F.name),n.uniformBlockBinding(re,Te,Te),ie.set(F,Te))}function se(F,re,ie){let xe=c.get(re).get(F);l[xe]!==ie&&(n.bindBufferBase(n.UNIFORM_BUFFER,xe,ie),l[xe]=ie)}function me(){n.disable(n.BLEND),n.disable(n.CULL_FACE),n.disable(n.DEPTH_TEST),n.disable(n.POLYGON_OFFSET_FILL),n.disable(n.SCISSOR_TEST),n.disable(n.STENCIL_TEST),n.disable(n.SAMPLE_ALPHA_TO_COVERAGE),n.blendEquation(n.FUNC_ADD),n.blendFunc(n.ONE,n.ZERO),n.blendFuncSeparate(n.ONE,n.ZERO,n.ONE,n.ZERO),n.blendColor(0,0,0,0),n.colorMask(!0,!0,!0,!0),n.clearColor(0,0,0,0),n.depthMask(!0),n.depthFunc(n.LESS),o.setReversed(!1),n.clearDepth(1),n.stencilMask(4294967295),n.stencilFunc(n.ALWAYS,0,4294967295),n.stencilOp(n.KEEP,n.KEEP,n.KEEP),n.clearStencil(0),n.cullFace(n.BACK),n.frontFace(n.CCW),n.polygonOffset(0,0),n.activeTexture(n.TEXTURE0),n.bindFramebuffer(n.FRAMEBUFFER,null),n.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),n.bindFramebuffer(n.READ_FRAMEBUFFER,null),n.useProgram(null),n.lineWidth(1),n.scissor(0,0,n.canvas.width,n.canvas.height),n.viewport(0,0,n.canvas.width,n.canvas.height),n.pixelStorei(n.PACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_ALIGNMENT,4),n.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,!1),n.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,!1),n.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,n.BROWSER_DEFAULT_WEBGL),n.pixelStorei(n.PACK_ROW_LENGTH,0),n.pixelStorei(n.PACK_SKIP_PIXELS,0),n.pixelStorei(n.PACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_ROW_LENGTH,0),n.pixelStorei(n.UNPACK_IMAGE_HEIGHT,0),n.pixelStorei(n.UNPACK_SKIP_PIXELS,0),n.pixelStorei(n.UNPACK_SKIP_ROWS,0),n.pixelStorei(n.UNPACK_SKIP_IMAGES,0),h={},f={},q=null,j={},u={},l={},p=new WeakMap,g=[],S=null,d=!1,m=null,y=null,A=null,b=null,C=null,E=null,x=null,T=new gt(0,0,0),k=0,U=!1,P=null,B=null,z=null,L=null,H=null,ee.set(0,0,n.canvas.width,n.canvas.height),pe.set(0,0,n.canvas.width,n.canvas.height),r.reset(),o.reset(),a.reset()}return{buffers:{color:r,depth:o,stencil:a},enable:ye,disable:qe,bindFramebuffer:it,drawBuffers:We,useProgram:Ce,setBlending:xt,setMaterial:Rt,setFlipSided:Bt,setCullFace:at,setLineWidth:Ct,setPolygonOffset:Ze,setScissorTest:ft,activeTexture:pt,bindTexture:bt,unbindTexture:O,compressedTexImage2D:Pe,compressedTexImage3D:je,texImage2D:v,texImage3D:Y,pixelStorei:oe,getParameter:ue,updateUBOMapping:ne,uniformBlockBinding:se,texStorage2D:Ke,texStorage3D:R,texSubImage2D:ht,texSubImage3D:Ee,compressedTexSubImage2D:Vt,compressedTexSubImage3D:Xe,scissor:ve,viewport:Se,reset:me}}function CE(n,e,t,i,s,r,o){let a=e.has("WEBGL_multisampled_render_to_texture")?e.get("WEBGL_multisampled_render_to_texture"):null,l=typeof navigator>"u"?!1:/OculusBrowser/g.test(navigator.userAgent),c=new ut,h=new WeakMap,f=new Set,u,p=new WeakMap,g=new Set,S=new FinalizationRegistry(R=>g.delete(R)),d=!1;try{d=typeof OffscreenCanvas<"u"&&new OffscreenCanvas(1,1).getContext("2d")!==null}catch{}function m(R,v){return d?new OffscreenCanvas(R,v):Ea("canvas")}function y(R,v,Y){let ue=1,oe=Ke(R);if((oe.width>Y||oe.height>Y)&&(ue=Y/Math.max(oe.width,oe.height)),ue<1)if(typeof HTMLImageElement<"u"&&R instanceof HTMLImageElement||typeof HTMLCanvasElement<"u"&&R instanceof HTMLCanvasElement||typeof ImageBitmap<"u"&&R instanceof ImageBitmap||typeof VideoFrame<"u"&&R instanceof VideoFrame){let ve=Math.floor(ue*oe.width),Se=Math.floor(ue*oe.height);u===void 0&&(u=m(ve,Se));let ne=v?m(ve,Se):u;return ne.width=ve,ne.height=Se,ne.getContext("2d").drawImage(R,0,0,ve,Se),Je("WebGLRenderer: Texture has been resized from ("+oe.width+"x"+oe.height+") to ("+ve+"x"+Se+")."),ne}else return"data"in R&&Je("WebGLRenderer: Image in DataTexture is too big ("+oe.width+"x"+oe.height+")."),R;return R}function A(R){return R.generateMipmaps}function b(R){n.generateMipmap(R)}function C(R){return R.isWebGLCubeRenderTarget?n.TEXTURE_CUBE_MAP:R.isWebGL3DRenderTarget?n.TEXTURE_3D:R.isWebGLArrayRenderTarget||R.isCompressedArrayTexture?n.TEXTURE_2D_ARRAY:n.TEXTURE_2D}function E(R,v,Y,ue,oe,ve=!1){if(R!==null){if(n[R]!==void 0)return n[R];Je("WebGLRenderer: Attempt to use non-existing WebGL internal format '"+R+"'")}let Se;ue&&(Se=e.get("EXT_texture_norm16"),Se||Je("WebGLRenderer: Unable to use normalized textures without EXT_texture_norm16 extension"));let ne=v;if(v===n.RED&&(Y===n.FLOAT&&(ne=n.R32F),Y===n.HALF_FLOAT&&(ne=n.R16F),Y===n.UNSIGNED_BYTE&&(ne=n.R8),Y===n.UNSIGNED_SHORT&&Se&&(ne=Se.R16_EXT),Y===n.SHORT&&Se&&(ne=Se.R16_SNORM_EXT)),v===n.RED_INTEGER&&(Y===n.UNSIGNED_BYTE&&(ne=n.R8UI),Y===n.UNSIGNED_SHORT&&(ne=n.R16UI),Y===n.UNSIGNED_INT&&(ne=n.R32UI),Y===n.BYTE&&(ne=n.R8I),Y===n.SHORT&&(ne=n.R16I),Y===n.INT&&(ne=n.R32I)),v===n.RG&&(Y===n.FLOAT&&(ne=n.RG32F),Y===n.HALF_FLOAT&&(ne=n.RG16F),Y===n.UNSIGNED_BYTE&&(ne=n.RG8),Y===n.UNSIGNED_SHORT&&Se&&(ne=Se.RG16_EXT),Y===n.SHORT&&Se&&(ne=Se.RG16_SNORM_EXT)),v===n.RG_INTEGER&&(Y===n.UNSIGNED_BYTE&&(ne=n.RG8UI),Y===n.UNSIGNED_SHORT&&(ne=n.RG16UI),Y===n.UNSIGNED_INT&&(ne=n.RG32UI),Y===n.BYTE&&(ne=n.RG8I),Y===n.SHORT&&(ne=n.RG16I),Y===n.INT&&(ne=n.RG32I)),v===n.RGB_INTEGER&&(Y===n.UNSIGNED_BYTE&&(ne=n.RGB8UI),Y===n.UNSIGNED_SHORT&&(ne=n.RGB16UI),Y===n.UNSIGNED_INT&&(ne=n.RGB32UI),Y===n.BYTE&&(ne=n.RGB8I),Y===n.SHORT&&(ne=n.RGB16I),Y===n.INT&&(ne=n.RGB32I)),v===n.RGBA_INTEGER&&(Y===n.UNSIGNED_BYTE&&(ne=n.RGBA8UI),Y===n.UNSIGNED_SHORT&&(ne=n.RGBA16UI),Y===n.UNSIGNED_INT&&(ne=n.RGBA32UI),Y===n.BYTE&&(ne=n.RGBA8I),Y===n.SHORT&&(ne=n.RGBA16I),Y===n.INT&&(ne=n.RGBA32I)),v===n.RGB&&(Y===n.UNSIGNED_SHORT&&Se&&(ne=Se.RGB16_EXT),Y===n.SHORT&&Se&&(ne=Se.RGB16_SNORM_EXT),Y===n.UNSIGNED_INT_5_9_9_9_REV&&(ne=n.RGB9_E5),Y===n.UNSIGNED_INT_10F_11F_11F_REV&&(ne=n.R11F_G11F_B10F)),v===n.RGBA){let se=ve?Ma:At.getTransfer(oe);Y===n.FLOAT&&(ne=n.RGBA32F),Y===n.HALF_FLOAT&&(ne=n.RGBA16F),Y===n.UNSIGNED_BYTE&&(ne=se===Ft?n.SRGB8_ALPHA8:n.RGBA8),Y===n.UNSIGNED_SHORT&&Se&&(ne=Se.RGBA16_EXT),Y===n.SHORT&&Se&&(ne=Se.RGBA16_SNORM_EXT),Y===n.UNSIGNED_SHORT_4_4_4_4&&(ne=n.RGBA4),Y===n.UNSIGNED_SHORT_5_5_5_1&&(ne=n.RGB5_A1)}return(ne===n.R16F||ne===n.R32F||ne===n.RG16F||ne===n.RG32F||ne===n.RGBA16F||ne===n.RGBA32F)&&e.get("EXT_color_buffer_float"),ne}function x(R,v){let Y;return R?v===null||v===Ui||v===Pr?Y=n.DEPTH24_STENCIL8:v===Oi?Y=n.DEPTH32F_STENCIL8:v===Uo&&(Y=n.DEPTH24_STENCIL8,Je("DepthTexture: 16 bit depth attachment is not supported with stencil. Using 24-bit attachment.")):v===null||v===Ui||v===Pr?Y=n.DEPTH_COMPONENT24:v===Oi?Y=n.DEPTH_COMPONENT32F:v===Uo&&(Y=n.DEPTH_COMPONENT16),Y}function T(R,v){return A(R)===!0||R.isFramebufferTexture&&R.minFilter!==Ln&&R.minFilter!==Yn?Math.log2(Math.max(v.width,v.height))+1:R.mipmaps.length>0?R.mipmaps.length:R.isCompressedTexture&&Array.isArray(R.image)?v.mipmaps.length:1}function k(R){let v=new WeakRef(R);i.get(R).__ref=v,g.add(v),S.register(R,v,v)}function U(R){let v=i.get(R).__ref;v!==void 0&&(g.delete(v),S.unregister(v))}function P(R){z(R.target)}function B(R){L(R.target)}function z(R){R.removeEventListener("dispose",P),U(R),W(R),R.isVideoTexture&&h.delete(R),R.isHTMLTexture&&f.delete(R)}function L(R){R.removeEventListener("dispose",B),U(R),te(R)}function H(){for(let R of g){let v=R.deref();v!==void 0&&(v.isRenderTarget===!0?L(v):z(v))}g.clear(),f.clear()}function W(R){let v=i.get(R);if(v.__webglInit===void 0)return;let Y=R.source,ue=p.get(Y);if(ue){let oe=ue[v.__cacheKey];oe.usedTimes--,oe.usedTimes===0&&D(R),Object.keys(ue).length===0&&p.delete(Y)}i.remove(R)}function D(R){let v=i.get(R);n.deleteTexture(v.__webglTexture);let Y=R.source,ue=p.get(Y);delete ue[v.__cacheKey],o.memory.textures--}function te(R){let v=i.get(R);v.__depthDisposeCallback&&v.__depthDisposeCallback();let Y=R.depthTexture;if(Y&&Y.renderTarget===R&&z(Y),R.isWebGLCubeRenderTarget)for(let oe=0;oe<6;oe++){if(Array.isArray(v.__webglFramebuffer[oe]))for(let ve=0;ve<v.__webglFramebuffer[oe].length;ve++)n.deleteFramebuffer(v.__webglFramebuffer[oe][ve]);else n.deleteFramebuffer(v.__webglFramebuffer[oe]);v.__webglDepthbuffer&&n.deleteRenderbuffer(v.__webglDepthbuffer[oe])}else{if(Array.isArray(v.__webglFramebuffer))for(let oe=0;oe<v.__webglFramebuffer.length;oe++)n.deleteFramebuffer(v.__webglFramebuffer[oe]);else n.deleteFramebuffer(v.__webglFramebuffer);if(v.__webglDepthbuffer&&n.deleteRenderbuffer(v.__webglDepthbuffer),v.__webglMultisampledFramebuffer&&n.deleteFramebuffer(v.__webglMultisampledFramebuffer),v.__webglColorRenderbuffer)for(let oe=0;oe<v.__webglColorRenderbuffer.length;oe++)v.__webglColorRenderbuffer[oe]&&n.deleteRenderbuffer(v.__webglColorRenderbuffer[oe]);v.__webglDepthRenderbuffer&&n.deleteRenderbuffer(v.__webglDepthRenderbuffer)}let ue=R.textures;for(let oe=0,ve=ue.length;oe<ve;oe++){let Se=i.get(ue[oe]);Se.__webglTexture&&(n.deleteTexture(Se.__webglTexture),o.memory.textures--),i.remove(ue[oe])}i.remove(R)}let X=0;function q(){X=0}function j(){return X}function ae(R){X=R}function ce(){let R=X;return R>=s.maxTextures&&Je("WebGLTextures: Trying to use "+(R+1)+" texture units while this GPU supports only "+s.maxTextures),X+=1,R}function ee(R){let v=[];return v.push(R.wrapS),v.push(R.wrapT),v.push(R.wrapR||0),v.push(R.magFilter),v.push(R.minFilter),v.push(R.anisotropy),v.push(R.internalFormat),v.push(R.format),v.push(R.type),v.push(R.generateMipmaps),v.push(R.mipmapsAutoUpdate),v.push(R.premultiplyAlpha),v.push(R.flipY),v.push(R.unpackAlignment),v.push(R.colorSpace),v.join()}function pe(R,v){let Y=i.get(R);if(R.isVideoTexture&&Vt(R),R.isRenderTargetTexture===!1&&R.isExternalTexture!==!0&&R.version>0&&Y.__version!==R.version){let ue=R.image;if(ue===null)Je("WebGLRenderer: Texture marked for update but no image data found.");else if(ue.complete===!1)Je("WebGLRenderer: Texture marked for update but image is incomplete");else{Rt(Y,R,v);return}}else R.isExternalTexture&&(Y.__webglTexture=R.sourceTexture?R.sourceTexture:null);t.bindTexture(n.TEXTURE_2D,Y.__webglTexture,n.TEXTURE0+v)}function fe(R,v){let Y=i.get(R);if(R.isRenderTargetTexture===!1&&R.version>0&&Y.__version!==R.version){Rt(Y,R,v);return}else R.isExternalTexture&&(Y.__webglTexture=R.sourceTexture?R.sourceTexture:null);t.bindTexture(n.TEXTURE_2D_ARRAY,Y.__webglTexture,n.TEXTURE0+v)}function Me(R,v){let Y=i.get(R);if(R.isRenderTargetTexture===!1&&R.version>0&&Y.__version!==R.version){Rt(Y,R,v);return}t.bindTexture(n.TEXTURE_3D,Y.__webglTexture,n.TEXTURE0+v)}function ye(R,v){let Y=i.get(R);if(R.version>0&&Y.__version!==R.version){Bt(Y,R,v);return}t.bindTexture(n.TEXTURE_CUBE_MAP,Y.__webglTexture,n.TEXTURE0+v)}let qe={[Sc]:n.REPEAT,[Ji]:n.CLAMP_TO_EDGE,[bc]:n.MIRRORED_REPEAT},it={[Ln]:n.NEAREST,[u0]:n.NEAREST_MIPMAP_NEAREST,[Va]:n.NEAREST_MIPMAP_LINEAR,[Yn]:n.LINEAR,[Jc]:n.LINEAR_MIPMAP_NEAREST,[ws]:n.LINEAR_MIPMAP_LINEAR},We={[m0]:n.NEVER,[ed]:n.ALWAYS,[g0]:n.LESS,[jf]:n.LEQUAL,[_0]:n.EQUAL,[Qf]:n.GEQUAL,[x0]:n.GREATER,[y0]:n.NOTEQUAL};function Ce(R,v){if(v.type===Oi&&e.has("OES_texture_float_linear")===!1&&(v.magFilter===Yn||v.magFilter===Jc||v.magFilter===Va||v.magFilter===ws||v.minFilter===Yn||v.minFilter===Jc||v.minFilter===Va||v.minFilter===ws)&&Je("WebGLRenderer: Unable to use linear filtering with floating point textures. OES_texture_float_linear not supported on this device."),n.texParameteri(R,n.TEXTURE_WRAP_S,qe[v.wrapS]),n.texParameteri(R,n.TEXTURE_WRAP_T,qe[v.wrapT]),(R===n.TEXTURE_3D||R===n.TEXTURE_2D_ARRAY)&&n.texParameteri(R,n.TEXTURE_WRAP_R,qe[v.wrapR]),n.texParameteri(R,n.TEXTURE_MAG_FILTER,it[v.magFilter]),n.texParameteri(R,n.TEXTURE_MIN_FILTER,it[v.minFilter]),v.compareFunction&&(n.texParameteri(R,n.TEXTURE_COMPARE_MODE,n.COMPARE_REF_TO_TEXTURE),n.texParameteri(R,n.TEXTURE_COMPARE_FUNC,We[v.compareFunction])),e.has("EXT_texture_filter_anisotropic")===!0){if(v.magFilter===Ln||v.minFilter!==Va&&v.minFilter!==ws||v.type===Oi&&e.has("OES_texture_float_linear")===!1)return;if(v.anisotropy>1||i.get(v).__currentAnisotropy){let Y=e.get("EXT_texture_filter_anisotropic");n.texParameterf(R,Y.TEXTURE_MAX_ANISOTROPY_EXT,Math.min(v.anisotropy,s.getMaxAnisotropy())),i.get(v).__currentAnisotropy=v.anisotropy}}}function Ne(R,v){let Y=!1;R.__webglInit===void 0&&(R.__webglInit=!0,v.addEventListener("dispose",P),k(v));let ue=v.source,oe=p.get(ue);oe===void 0&&(oe={},p.set(ue,oe));let ve=ee(v);if(ve!==R.__cacheKey){oe[ve]===void 0&&(oe[ve]={texture:n.createTexture(),usedTimes:0},o.memory.textures++,Y=!0),oe[ve].usedTimes++;let Se=oe[R.__cacheKey];Se!==void 0&&(oe[R.__cacheKey].usedTimes--,Se.usedTimes===0&&D(v)),R.__cacheKey=ve,R.__webglTexture=oe[ve].texture}return Y}function Be(R,v,Y){return Math.floor(Math.floor(R/Y)/v)}function xt(R,v,Y,ue){let ve=R.updateRanges;if(ve.length===0)t.texSubImage2D(n.TEXTURE_2D,0,0,0,v.width,v.height,Y,ue,v.data);else{ve.sort((F,re)=>F.start-re.start);let Se=0;for(let F=1;F<ve.length;F++){let re=ve[Se],ie=ve[F],Te=re.start+re.count,xe=Be(ie.start,v.width,4),we=Be(re.start,v.width,4);ie.start<=Te+1&&xe===we&&Be(ie.start+ie.count-1,v.width,4)===xe?re.count=Math.max(re.count,ie.start+ie.count-re.start):(++Se,ve[Se]=ie)}ve.length=Se+1;let ne=t.getParameter(n.UNPACK_ROW_LENGTH),se=t.getParameter(n.UNPACK_SKIP_PIXELS),me=t.getParameter(n.UNPACK_SKIP_ROWS);t.pixelStorei(n.UNPACK_ROW_LENGTH,v.width);for(let F=0,re=ve.length;F<re;F++){let ie=ve[F],Te=Math.floor(ie.start/4),xe=Math.ceil(ie.count/4),we=Te%v.width,Ye=Math.floor(Te/v.width),tt=xe,he=1;t.pixelStorei(n.UNPACK_SKIP_PIXELS,we),t.pixelStorei(n.UNPACK_SKIP_ROWS,Ye),t.texSubImage2D(n.TEXTURE_2D,0,we,Ye,tt,he,Y,ue,v.data)}R.clearUpdateRanges(),t.pixelStorei(n.UNPACK_ROW_LENGTH,ne),t.pixelStorei(n.UNPACK_SKIP_PIXELS,se),t.pixelStorei(n.UNPACK_SKIP_ROWS,me)}}function Rt(R,v,Y){let ue=n.TEXTURE_2D;(v.isDataArrayTexture||v.isCompressedArrayTexture)&&(ue=n.TEXTURE_2D_ARRAY),v.isData3DTexture&&(ue=n.TEXTURE_3D);let oe=Ne(R,v),ve=v.source;t.bindTexture(ue,R.__webglTexture,n.TEXTURE0+Y);let Se=i.get(ve);if(ve.version!==Se.__version||oe===!0){if(t.activeTexture(n.TEXTURE0+Y),(typeof ImageBitmap<"u"&&v.image instanceof ImageBitmap)===!1){let he=At.getPrimaries(At.workingColorSpace),Ge=v.colorSpace===Ts?null:At.getPrimaries(v.colorSpace),nt=v.colorSpace===Ts||he===Ge?n.NONE:n.BROWSER_DEFAULT_WEBGL;t.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,v.flipY),t.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,v.premultiplyAlpha),t.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,nt)}t.pixelStorei(n.UNPACK_ALIGNMENT,v.unpackAlignment);let se=y(v.image,!1,s.maxTextureSize);se=Xe(v,se);let me=r.convert(v.format,v.colorSpace),F=r.convert(v.type),re=E(v.internalFormat,me,F,v.normalized,v.colorSpace,v.isVideoTexture);Ce(ue,v);let ie,Te=v.mipmaps,xe=v.isVideoTexture!==!0,we=Se.__version===void 0||oe===!0,Ye=ve.dataReady,tt=T(v,se);if(v.isDepthTexture)re=x(v.format===Es,v.type),we&&(xe?t.texStorage2D(n.TEXTURE_2D,1,re,se.width,se.height):t.texImage2D(n.TEXTURE_2D,0,re,se.width,se.height,0,me,F,null));else if(v.isDataTexture)if(Te.length>0){xe&&we&&t.texStorage2D(n.TEXTURE_2D,tt,re,Te[0].width,Te[0].height);for(let he=0,Ge=Te.length;he<Ge;he++)ie=Te[he],xe?Ye&&t.texSubImage2D(n.TEXTURE_2D,he,0,0,ie.width,ie.height,me,F,ie.data):t.texImage2D(n.TEXTURE_2D,he,re,ie.width,ie.height,0,me,F,ie.data);v.generateMipmaps=!1}else xe?(we&&t.texStorage2D(n.TEXTURE_2D,tt,re,se.width,se.height),Ye&&xt(v,se,me,F)):t.texImage2D(n.TEXTURE_2D,0,re,se.width,se.height,0,me,F,se.data);else if(v.isCompressedTexture)if(v.isCompressedArrayTexture){xe&&we&&t.texStorage3D(n.TEXTURE_2D_ARRAY,tt,re,Te[0].width,Te[0].height,se.depth);for(let he=0,Ge=Te.length;he<Ge;he++)if(ie=Te[he],v.format!==Bi)if(me!==null)if(xe){if(Ye)if(v.layerUpdates.size>0){let nt=hd(ie.width,ie.height,v.format,v.type);for(let Ie of v.layerUpdates){let dt=ie.data.subarray(Ie*nt/ie.data.BYTES_PER_ELEMENT,(Ie+1)*nt/ie.data.BYTES_PER_ELEMENT);t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,he,0,0,Ie,ie.width,ie.height,1,me,dt)}}else t.compressedTexSubImage3D(n.TEXTURE_2D_ARRAY,he,0,0,0,ie.width,ie.height,se.depth,me,ie.data)}else t.compressedTexImage3D(n.TEXTURE_2D_ARRAY,he,re,ie.width,ie.height,se.depth,0,ie.data,0,0);else Je("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()");else xe?Ye&&t.texSubImage3D(n.TEXTURE_2D_ARRAY,he,0,0,0,ie.width,ie.height,se.depth,me,F,ie.data):t.texImage3D(n.TEXTURE_2D_ARRAY,he,re,ie.width,ie.height,se.depth,0,me,F,ie.data);v.layerUpdates.size>0&&v.clearLayerUpdates()}else{xe&&we&&t.texStorage2D(n.TEXTURE_2D,tt,re,Te[0].width,Te[0].height);for(let he=0,Ge=Te.length;he<Ge;he++)ie=Te[he],v.format!==Bi?me!==null?xe?Ye&&t.compressedTexSubImage2D(n.TEXTURE_2D,he,0,0,ie.width,ie.height,me,ie.data):t.compressedTexImage2D(n.TEXTURE_2D,he,re,ie.width,ie.height,0,ie.data):Je("WebGLRenderer: Attempt to load unsupported compressed texture format in .uploadTexture()"):xe?Ye&&t.texSubImage2D(n.TEXTURE_2D,he,0,0,ie.width,ie.height,me,F,ie.data):t.texImage2D(n.TEXTURE_2D,he,re,ie.width,ie.height,0,me,F,ie.data)}else if(v.isDataArrayTexture)if(xe){if(we&&t.texStorage3D(n.TEXTURE_2D_ARRAY,tt,re,se.width,se.height,se.depth),Ye)if(v.layerUpdates.size>0){let he=hd(se.width,se.height,v.format,v.type);for(let Ge of v.layerUpdates){let nt=se.data.subarray(Ge*he/se.data.BYTES_PER_ELEMENT,(Ge+1)*he/se.data.BYTES_PER_ELEMENT);t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,Ge,se.width,se.height,1,me,F,nt)}v.clearLayerUpdates()}else t.texSubImage3D(n.TEXTURE_2D_ARRAY,0,0,0,0,se.width,se.height,se.depth,me,F,se.data)}else t.texImage3D(n.TEXTURE_2D_ARRAY,0,re,se.width,se.height,se.depth,0,me,F,se.data);else if(v.isData3DTexture)xe?(we&&t.texStorage3D(n.TEXTURE_3D,tt,re,se.width,se.height,se.depth),Ye&&t.texSubImage3D(n.TEXTURE_3D,0,0,0,0,se.width,se.height,se.depth,me,F,se.data)):t.texImage3D(n.TEXTURE_3D,0,re,se.width,se.height,se.depth,0,me,F,se.data);else if(v.isFramebufferTexture){if(we)if(xe)t.texStorage2D(n.TEXTURE_2D,tt,re,se.width,se.height);else{let he=se.width,Ge=se.height;for(let nt=0;nt<tt;nt++)t.texImage2D(n.TEXTURE_2D,nt,re,he,Ge,0,me,F,null),he>>=1,Ge>>=1}}else if(v.isHTMLTexture){if("texElementImage2D"in n){let he=n.canvas;if(he.hasAttribute("layoutsubtree")||he.setAttribute("layoutsubtree","true"),se.parentNode!==he){he.appendChild(se),f.add(v),he.onpaint=Ge=>{let nt=Ge.changedElements;for(let Ie of f)nt.includes(Ie.image)&&(Ie.needsUpdate=!0)},he.requestPaint();return}if(n.texElementImage2D.length===3)n.texElementImage2D(n.TEXTURE_2D,n.RGBA8,se);else{let nt=n.RGBA,Ie=n.RGBA,dt=n.UNSIGNED_BYTE;n.texElementImage2D(n.TEXTURE_2D,0,nt,Ie,dt,se)}n.texParameteri(n.TEXTURE_2D,n.TEXTURE_MIN_FILTER,n.LINEAR),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_S,n.CLAMP_TO_EDGE),n.texParameteri(n.TEXTURE_2D,n.TEXTURE_WRAP_T,n.CLAMP_TO_EDGE)}}else if(Te.length>0){if(xe&&we){let he=Ke(Te[0]);t.texStorage2D(n.TEXTURE_2D,tt,re,he.width,he.height)}for(let he=0,Ge=Te.length;he<Ge;he++)ie=Te[he],xe?Ye&&t.texSubImage2D(n.TEXTURE_2D,he,0,0,me,F,ie):t.texImage2D(n.TEXTURE_2D,he,re,me,F,ie);v.generateMipmaps=!1}else if(xe){if(we){let he=Ke(se);t.texStorage2D(n.TEXTURE_2D,tt,re,he.width,he.height)}Ye&&t.texSubImage2D(n.TEXTURE_2D,0,0,0,me,F,se)}else t.texImage2D(n.TEXTURE_2D,0,re,me,F,se);A(v)&&v.mipmapsAutoUpdate===!0&&b(ue),Se.__version=ve.version,v.onUpdate&&v.onUpdate(v)}R.__version=v.version}function Bt(R,v,Y){if(v.image.length!==6)return;let ue=Ne(R,v),oe=v.source;t.bindTexture(n.TEXTURE_CUBE_MAP,R.__webglTexture,n.TEXTURE0+Y);let ve=i.get(oe);if(oe.version!==ve.__version||ue===!0){t.activeTexture(n.TEXTURE0+Y);let Se=At.getPrimaries(At.workingColorSpace),ne=v.colorSpace===Ts?null:At.getPrimaries(v.colorSpace),se=v.colorSpace===Ts||Se===ne?n.NONE:n.BROWSER_DEFAULT_WEBGL;t.pixelStorei(n.UNPACK_FLIP_Y_WEBGL,v.flipY),t.pixelStorei(n.UNPACK_PREMULTIPLY_ALPHA_WEBGL,v.premultiplyAlpha),t.pixelStorei(n.UNPACK_ALIGNMENT,v.unpackAlignment),t.pixelStorei(n.UNPACK_COLORSPACE_CONVERSION_WEBGL,se);let me=v.isCompressedTexture||v.image[0].isCompressedTexture,F=v.image[0]&&v.image[0].isDataTexture,re=[];for(let Ie=0;Ie<6;Ie++)!me&&!F?re[Ie]=y(v.image[Ie],!0,s.maxCubemapSize):re[Ie]=F?v.image[Ie].image:v.image[Ie],re[Ie]=Xe(v,re[Ie]);let ie=re[0],Te=r.convert(v.format,v.colorSpace),xe=r.convert(v.type),we=E(v.internalFormat,Te,xe,v.normalized,v.colorSpace),Ye=v.isVideoTexture!==!0,tt=ve.__version===void 0||ue===!0,he=oe.dataReady,Ge=T(v,ie);Ce(n.TEXTURE_CUBE_MAP,v);let nt;if(v.isDepthTexture){if(we=x(v.format===Es,v.type),tt)if(Ye)t.texStorage2D(n.TEXTURE_CUBE_MAP,1,we,ie.width,ie.height);else for(let Ie=0;Ie<6;Ie++)t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Ie,0,we,ie.width,ie.height,0,Te,xe,null)}else if(me){Ye&&tt&&t.texStorage2D(n.TEXTURE_CUBE_MAP,Ge,we,ie.width,ie.height);for(let Ie=0;Ie<6;Ie++){nt=re[Ie].mipmaps;for(let dt=0;dt<nt.length;dt++){let qt=nt[dt];v.format!==Bi?Te!==null?Ye?he&&t.compressedTexSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Ie,dt,0,0,qt.width,qt.height,Te,qt.data):t.compressedTexImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Ie,dt,we,qt.width,qt.height,0,qt.data):Je("WebGLRenderer: Attempt to load unsupported compressed texture format in .setTextureCube()"):Ye?he&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Ie,dt,0,0,qt.width,qt.height,Te,xe,qt.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Ie,dt,we,qt.width,qt.height,0,Te,xe,qt.data)}}}else{if(nt=v.mipmaps,Ye&&tt){nt.length>0&&Ge++;let Ie=Ke(re[0]);t.texStorage2D(n.TEXTURE_CUBE_MAP,Ge,we,Ie.width,Ie.height)}for(let Ie=0;Ie<6;Ie++)if(F){Ye?he&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Ie,0,0,0,re[Ie].width,re[Ie].height,Te,xe,re[Ie].data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Ie,0,we,re[Ie].width,re[Ie].height,0,Te,xe,re[Ie].data);for(let dt=0;dt<nt.length;dt++){let zn=nt[dt].image[Ie].image;Ye?he&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Ie,dt+1,0,0,zn.width,zn.height,Te,xe,zn.data):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Ie,dt+1,we,zn.width,zn.height,0,Te,xe,zn.data)}}else{Ye?he&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Ie,0,0,0,Te,xe,re[Ie]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Ie,0,we,Te,xe,re[Ie]);for(let dt=0;dt<nt.length;dt++){let qt=nt[dt];Ye?he&&t.texSubImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Ie,dt+1,0,0,Te,xe,qt.image[Ie]):t.texImage2D(n.TEXTURE_CUBE_MAP_POSITIVE_X+Ie,dt+1,we,Te,xe,qt.image[Ie])}}}A(v)&&v.mipmapsAutoUpdate===!0&&b(n.TEXTURE_CUBE_MAP),ve.__version=oe.version,v.onUpdate&&v.onUpdate(v)}R.__version=v.version}function at(R,v,Y,ue,oe,ve){let Se=r.convert(Y.format,Y.colorSpace),ne=r.convert(Y.type),se=E(Y.internalFormat,Se,ne,Y.normalized,Y.colorSpace),me=i.get(v),F=i.get(Y);if(F.__renderTarget=v,!me.__hasExternalTextures){let re=Math.max(1,v.width>>ve),ie=Math.max(1,v.height>>ve);oe===n.TEXTURE_3D||oe===n.TEXTURE_2D_ARRAY?t.texImage3D(oe,ve,se,re,ie,v.depth,0,Se,ne,null):t.texImage2D(oe,ve,se,re,ie,0,Se,ne,null)}t.bindFramebuffer(n.FRAMEBUFFER,R),Ee(v)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,ue,oe,F.__webglTexture,0,ht(v)):(oe===n.TEXTURE_2D||oe>=n.TEXTURE_CUBE_MAP_POSITIVE_X&&oe<=n.TEXTURE_CUBE_MAP_NEGATIVE_Z)&&n.framebufferTexture2D(n.FRAMEBUFFER,ue,oe,F.__webglTexture,ve),t.bindFramebuffer(n.FRAMEBUFFER,null)}function Ct(R,v,Y){if(n.bindRenderbuffer(n.RENDERBUFFER,R),v.depthBuffer){let ue=v.depthTexture,oe=ue&&ue.isDepthTexture?ue.type:null,ve=x(v.stencilBuffer,oe),Se=v.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;Ee(v)?a.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,ht(v),ve,v.width,v.height):Y?n.renderbufferStorageMultisample(n.RENDERBUFFER,ht(v),ve,v.width,v.height):n.renderbufferStorage(n.RENDERBUFFER,ve,v.width,v.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,Se,n.RENDERBUFFER,R)}else{let ue=v.textures;for(let oe=0;oe<ue.length;oe++){let ve=ue[oe],Se=r.convert(ve.format,ve.colorSpace),ne=r.convert(ve.type),se=E(ve.internalFormat,Se,ne,ve.normalized,ve.colorSpace);Ee(v)?a.renderbufferStorageMultisampleEXT(n.RENDERBUFFER,ht(v),se,v.width,v.height):Y?n.renderbufferStorageMultisample(n.RENDERBUFFER,ht(v),se,v.width,v.height):n.renderbufferStorage(n.RENDERBUFFER,se,v.width,v.height)}}n.bindRenderbuffer(n.RENDERBUFFER,null)}function Ze(R,v,Y){let ue=v.isWebGLCubeRenderTarget===!0;if(t.bindFramebuffer(n.FRAMEBUFFER,R),!(v.depthTexture&&v.depthTexture.isDepthTexture))throw new Error("THREE.WebGLTextures: renderTarget.depthTexture must be an instance of THREE.DepthTexture.");let oe=i.get(v.depthTexture);oe.__renderTarget=v;let ve=ue?v.depthTexture.image[0]:v.depthTexture.image;(!oe.__webglTexture||ve.width!==v.width||ve.height!==v.height)&&(ve.width=v.width,ve.height=v.height,v.depthTexture.needsUpdate=!0),ue?ye(v.depthTexture,0):pe(v.depthTexture,0);let Se=oe.__webglTexture,ne=ht(v),se=ue?n.TEXTURE_CUBE_MAP_POSITIVE_X+Y:n.TEXTURE_2D,me=v.depthTexture.format===Es?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;if(v.depthTexture.format===Ss)Ee(v)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,me,se,Se,0,ne):n.framebufferTexture2D(n.FRAMEBUFFER,me,se,Se,0);else if(v.depthTexture.format===Es)Ee(v)?a.framebufferTexture2DMultisampleEXT(n.FRAMEBUFFER,me,se,Se,0,ne):n.framebufferTexture2D(n.FRAMEBUFFER,me,se,Se,0);else throw new Error("THREE.WebGLTextures: Unknown depthTexture format.")}function ft(R){let v=i.get(R),Y=R.isWebGLCubeRenderTarget===!0;if(v.__boundDepthTexture!==R.depthTexture){let ue=R.depthTexture;if(v.__depthDisposeCallback&&v.__depthDisposeCallback(),ue){let oe=()=>{delete v.__boundDepthTexture,delete v.__depthDisposeCallback,ue.removeEventListener("dispose",oe)};ue.addEventListener("dispose",oe),v.__depthDisposeCallback=oe}v.__boundDepthTexture=ue}if(R.depthTexture&&!v.__autoAllocateDepthBuffer)if(Y)for(let ue=0;ue<6;ue++)Ze(v.__webglFramebuffer[ue],R,ue);else R.texture.mipmaps.length>0?Ze(v.__webglFramebuffer[0],R,0):Ze(v.__webglFramebuffer,R,0);else if(Y){v.__webglDepthbuffer=[];for(let ue=0;ue<6;ue++)if(t.bindFramebuffer(n.FRAMEBUFFER,v.__webglFramebuffer[ue]),v.__webglDepthbuffer[ue]===void 0)v.__webglDepthbuffer[ue]=n.createRenderbuffer(),Ct(v.__webglDepthbuffer[ue],R,!1);else{let oe=R.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,ve=v.__webglDepthbuffer[ue];n.bindRenderbuffer(n.RENDERBUFFER,ve),n.framebufferRenderbuffer(n.FRAMEBUFFER,oe,n.RENDERBUFFER,ve)}}else if(R.texture.mipmaps.length>0?t.bindFramebuffer(n.FRAMEBUFFER,v.__webglFramebuffer[0]):t.bindFramebuffer(n.FRAMEBUFFER,v.__webglFramebuffer),v.__webglDepthbuffer===void 0)v.__webglDepthbuffer=n.createRenderbuffer(),Ct(v.__webglDepthbuffer,R,!1);else{let oe=R.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,ve=v.__webglDepthbuffer;n.bindRenderbuffer(n.RENDERBUFFER,ve),n.framebufferRenderbuffer(n.FRAMEBUFFER,oe,n.RENDERBUFFER,ve)}t.bindFramebuffer(n.FRAMEBUFFER,null)}function pt(R,v,Y){let ue=i.get(R);v!==void 0&&at(ue.__webglFramebuffer,R,R.texture,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,0),Y!==void 0&&ft(R)}function bt(R){let v=R.texture,Y=i.get(R),ue=i.get(v);R.addEventListener("dispose",B),k(R);let oe=R.textures,ve=R.isWebGLCubeRenderTarget===!0,Se=oe.length>1;if(Se||(ue.__webglTexture===void 0&&(ue.__webglTexture=n.createTexture()),ue.__version=v.version,o.memory.textures++),ve){Y.__webglFramebuffer=[];for(let ne=0;ne<6;ne++)if(v.mipmaps.length>0){Y.__webglFramebuffer[ne]=[];for(let se=0;se<v.mipmaps.length;se++)Y.__webglFramebuffer[ne][se]=n.createFramebuffer()}else Y.__webglFramebuffer[ne]=n.createFramebuffer()}else{if(v.mipmaps.length>0){Y.__webglFramebuffer=[];for(let ne=0;ne<v.mipmaps.length;ne++)Y.__webglFramebuffer[ne]=n.createFramebuffer()}else Y.__webglFramebuffer=n.createFramebuffer();if(Se)for(let ne=0,se=oe.length;ne<se;ne++){let me=i.get(oe[ne]);me.__webglTexture===void 0&&(me.__webglTexture=n.createTexture(),o.memory.textures++)}if(R.samples>0&&Ee(R)===!1){Y.__webglMultisampledFramebuffer=n.createFramebuffer(),Y.__webglColorRenderbuffer=[],t.bindFramebuffer(n.FRAMEBUFFER,Y.__webglMultisampledFramebuffer);for(let ne=0;ne<oe.length;ne++){let se=oe[ne];Y.__webglColorRenderbuffer[ne]=n.createRenderbuffer(),n.bindRenderbuffer(n.RENDERBUFFER,Y.__webglColorRenderbuffer[ne]);let me=r.convert(se.format,se.colorSpace),F=r.convert(se.type),re=E(se.internalFormat,me,F,se.normalized,se.colorSpace,R.isXRRenderTarget===!0),ie=ht(R);n.renderbufferStorageMultisample(n.RENDERBUFFER,ie,re,R.width,R.height),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+ne,n.RENDERBUFFER,Y.__webglColorRenderbuffer[ne])}n.bindRenderbuffer(n.RENDERBUFFER,null),R.depthBuffer&&(Y.__webglDepthRenderbuffer=n.createRenderbuffer(),Ct(Y.__webglDepthRenderbuffer,R,!0)),t.bindFramebuffer(n.FRAMEBUFFER,null)}}if(ve){t.bindTexture(n.TEXTURE_CUBE_MAP,ue.__webglTexture),Ce(n.TEXTURE_CUBE_MAP,v);for(let ne=0;ne<6;ne++)if(v.mipmaps.length>0)for(let se=0;se<v.mipmaps.length;se++)at(Y.__webglFramebuffer[ne][se],R,v,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+ne,se);else at(Y.__webglFramebuffer[ne],R,v,n.COLOR_ATTACHMENT0,n.TEXTURE_CUBE_MAP_POSITIVE_X+ne,0);A(v)?b(n.TEXTURE_CUBE_MAP):v.mipmaps.length>0&&n.texParameteri(n.TEXTURE_CUBE_MAP,n.TEXTURE_MAX_LEVEL,v.mipmaps.length-1),t.unbindTexture()}else if(Se){for(let ne=0,se=oe.length;ne<se;ne++){let me=oe[ne],F=i.get(me),re=n.TEXTURE_2D;(R.isWebGL3DRenderTarget||R.isWebGLArrayRenderTarget)&&(re=R.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),t.bindTexture(re,F.__webglTexture),Ce(re,me),at(Y.__webglFramebuffer,R,me,n.COLOR_ATTACHMENT0+ne,re,0),A(me)&&b(re)}t.unbindTexture()}else{let ne=n.TEXTURE_2D;if((R.isWebGL3DRenderTarget||R.isWebGLArrayRenderTarget)&&(ne=R.isWebGL3DRenderTarget?n.TEXTURE_3D:n.TEXTURE_2D_ARRAY),t.bindTexture(ne,ue.__webglTexture),Ce(ne,v),v.mipmaps.length>0)for(let se=0;se<v.mipmaps.length;se++)at(Y.__webglFramebuffer[se],R,v,n.COLOR_ATTACHMENT0,ne,se);else at(Y.__webglFramebuffer,R,v,n.COLOR_ATTACHMENT0,ne,0);A(v)?b(ne):v.mipmaps.length>0&&n.texParameteri(ne,n.TEXTURE_MAX_LEVEL,v.mipmaps.length-1),t.unbindTexture()}R.depthBuffer&&ft(R)}function O(R){let v=R.textures;for(let Y=0,ue=v.length;Y<ue;Y++){let oe=v[Y];if(A(oe)&&oe.mipmapsAutoUpdate===!0){let ve=C(R),Se=i.get(oe).__webglTexture;t.bindTexture(ve,Se),b(ve),t.unbindTexture()}}}let Pe=[];function je(R){if(R.samples>0){if(Ee(R)===!1){let v=R.textures,Y=R.width,ue=R.height,oe=n.COLOR_BUFFER_BIT,ve=R.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT,Se=i.get(R),ne=v.length>1;if(ne)for(let me=0;me<v.length;me++)t.bindFramebuffer(n.FRAMEBUFFER,Se.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+me,n.RENDERBUFFER,null),t.bindFramebuffer(n.FRAMEBUFFER,Se.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+me,n.TEXTURE_2D,null,0);t.bindFramebuffer(n.READ_FRAMEBUFFER,Se.__webglMultisampledFramebuffer),R.texture.mipmaps.length>0?t.bindFramebuffer(n.DRAW_FRAMEBUFFER,Se.__webglFramebuffer[0]):t.bindFramebuffer(n.DRAW_FRAMEBUFFER,Se.__webglFramebuffer);for(let me=0;me<v.length;me++){if(R.resolveDepthBuffer&&(R.depthBuffer&&(oe|=n.DEPTH_BUFFER_BIT),R.stencilBuffer&&R.resolveStencilBuffer&&(oe|=n.STENCIL_BUFFER_BIT)),ne){n.framebufferRenderbuffer(n.READ_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.RENDERBUFFER,Se.__webglColorRenderbuffer[me]);let F=i.get(v[me]).__webglTexture;n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0,n.TEXTURE_2D,F,0)}n.blitFramebuffer(0,0,Y,ue,0,0,Y,ue,oe,n.NEAREST),l===!0&&(Pe.length=0,Pe.push(n.COLOR_ATTACHMENT0+me),R.depthBuffer&&R.storeMultisampledDepthBuffer===!1&&Pe.push(ve),n.invalidateFramebuffer(n.READ_FRAMEBUFFER,Pe))}if(t.bindFramebuffer(n.READ_FRAMEBUFFER,null),t.bindFramebuffer(n.DRAW_FRAMEBUFFER,null),ne)for(let me=0;me<v.length;me++){t.bindFramebuffer(n.FRAMEBUFFER,Se.__webglMultisampledFramebuffer),n.framebufferRenderbuffer(n.FRAMEBUFFER,n.COLOR_ATTACHMENT0+me,n.RENDERBUFFER,Se.__webglColorRenderbuffer[me]);let F=i.get(v[me]).__webglTexture;t.bindFramebuffer(n.FRAMEBUFFER,Se.__webglFramebuffer),n.framebufferTexture2D(n.DRAW_FRAMEBUFFER,n.COLOR_ATTACHMENT0+me,n.TEXTURE_2D,F,0)}t.bindFramebuffer(n.DRAW_FRAMEBUFFER,Se.__webglMultisampledFramebuffer)}else if(R.depthBuffer&&R.storeMultisampledDepthBuffer===!1&&l){let v=R.stencilBuffer?n.DEPTH_STENCIL_ATTACHMENT:n.DEPTH_ATTACHMENT;n.invalidateFramebuffer(n.DRAW_FRAMEBUFFER,[v])}}}function ht(R){return Math.min(s.maxSamples,R.samples)}function Ee(R){let v=i.get(R);return R.samples>0&&e.has("WEBGL_multisampled_render_to_texture")===!0&&v.__useRenderToTexture!==!1}function Vt(R){let v=o.render.frame;h.get(R)!==v&&(h.set(R,v),R.update())}function Xe(R,v){let Y=R.colorSpace,ue=R.format,oe=R.type;return R.isCompressedTexture===!0||R.isVideoTexture===!0||Y!==ba&&Y!==Ts&&(At.getTransfer(Y)===Ft?(ue!==Bi||oe!==gi)&&Je("WebGLTextures: sRGB encoded textures have to use RGBAFormat and UnsignedByteType."):rt("WebGLTextures: Unsupported texture color space:",Y)),v}function Ke(R){return typeof HTMLImageElement<"u"&&R instanceof HTMLImageElement?(c.width=R.naturalWidth||R.width,c.height=R.naturalHeight||R.height):typeof VideoFrame<"u"&&R instanceof VideoFrame?(c.width=R.displayWidth,c.height=R.displayHeight):(c.width=R.width,c.height=R.height),c}this.allocateTextureUnit=ce,this.resetTextureUnits=q,this.getTextureUnits=j,this.setTextureUnits=ae,this.setTexture2D=pe,this.setTexture2DArray=fe,this.setTexture3D=Me,this.setTextureCube=ye,this.rebindTextures=pt,this.setupRenderTarget=bt,this.updateRenderTargetMipmap=O,this.updateMultisampleRenderTarget=je,this.setupDepthRenderbuffer=ft,this.setupFrameBufferTexture=at,this.useMultisampledRTT=Ee,this.dispose=H}function IE(n,e){function t(i,s=Ts){let r,o=At.getTransfer(s);if(i===gi)return n.UNSIGNED_BYTE;if(i===Qc)return n.UNSIGNED_SHORT_4_4_4_4;if(i===eh)return n.UNSIGNED_SHORT_5_5_5_1;if(i===qf)return n.UNSIGNED_INT_5_9_9_9_REV;if(i===Yf)return n.UNSIGNED_INT_10F_11F_11F_REV;if(i===Wf)return n.BYTE;if(i===Xf)return n.SHORT;if(i===Uo)return n.UNSIGNED_SHORT;if(i===jc)return n.INT;if(i===Ui)return n.UNSIGNED_INT;if(i===Oi)return n.FLOAT;if(i===Fi)return n.HALF_FLOAT;if(i===$f)return n.ALPHA;if(i===Zf)return n.RGB;if(i===Bi)return n.RGBA;if(i===Ss)return n.DEPTH_COMPONENT;if(i===Es)return n.DEPTH_STENCIL;if(i===Kf)return n.RED;if(i===th)return n.RED_INTEGER;if(i===or)return n.RG;if(i===nh)return n.RG_INTEGER;if(i===ih)return n.RGBA_INTEGER;if(i===Wa||i===Xa||i===qa||i===Ya)if(o===Ft)if(r=e.get("WEBGL_compressed_texture_s3tc_srgb"),r!==null){if(i===Wa)return r.COMPRESSED_SRGB_S3TC_DXT1_EXT;if(i===Xa)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT;if(i===qa)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT;if(i===Ya)return r.COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT}else return null;else if(r=e.get("WEBGL_compressed_texture_s3tc"),r!==null){if(i===Wa)return r.COMPRESSED_RGB_S3TC_DXT1_EXT;if(i===Xa)return r.COMPRESSED_RGBA_S3TC_DXT1_EXT;if(i===qa)return r.COMPRESSED_RGBA_S3TC_DXT3_EXT;if(i===Ya)return r.COMPRESSED_RGBA_S3TC_DXT5_EXT}else return null;if(i===sh||i===rh||i===oh||i===ah)if(r=e.get("WEBGL_compressed_texture_pvrtc"),r!==null){if(i===sh)return r.COMPRESSED_RGB_PVRTC_4BPPV1_IMG;if(i===rh)return r.COMPRESSED_RGB_PVRTC_2BPPV1_IMG;if(i===oh)return r.COMPRESSED_RGBA_PVRTC_4BPPV1_IMG;if(i===ah)return r.COMPRESSED_RGBA_PVRTC_2BPPV1_IMG}else return null;if(i===lh||i===ch||i===hh||i===uh||i===fh||i===$a||i===dh)if(r=e.get("WEBGL_compressed_texture_etc"),r!==null){if(i===lh||i===ch)return o===Ft?r.COMPRESSED_SRGB8_ETC2:r.COMPRESSED_RGB8_ETC2;if(i===hh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ETC2_EAC:r.COMPRESSED_RGBA8_ETC2_EAC;if(i===uh)return r.COMPRESSED_R11_EAC;if(i===fh)return r.COMPRESSED_SIGNED_R11_EAC;if(i===$a)return r.COMPRESSED_RG11_EAC;if(i===dh)return r.COMPRESSED_SIGNED_RG11_EAC}else return null;if(i===ph||i===mh||i===gh||i===_h||i===xh||i===yh||i===vh||i===Sh||i===bh||i===Mh||i===wh||i===Eh||i===Th||i===Ah)if(r=e.get("WEBGL_compressed_texture_astc"),r!==null){if(i===ph)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_4x4_KHR:r.COMPRESSED_RGBA_ASTC_4x4_KHR;if(i===mh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x4_KHR:r.COMPRESSED_RGBA_ASTC_5x4_KHR;if(i===gh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_5x5_KHR:r.COMPRESSED_RGBA_ASTC_5x5_KHR;if(i===_h)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x5_KHR:r.COMPRESSED_RGBA_ASTC_6x5_KHR;if(i===xh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_6x6_KHR:r.COMPRESSED_RGBA_ASTC_6x6_KHR;if(i===yh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x5_KHR:r.COMPRESSED_RGBA_ASTC_8x5_KHR;if(i===vh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x6_KHR:r.COMPRESSED_RGBA_ASTC_8x6_KHR;if(i===Sh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_8x8_KHR:r.COMPRESSED_RGBA_ASTC_8x8_KHR;if(i===bh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x5_KHR:r.COMPRESSED_RGBA_ASTC_10x5_KHR;if(i===Mh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x6_KHR:r.COMPRESSED_RGBA_ASTC_10x6_KHR;if(i===wh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x8_KHR:r.COMPRESSED_RGBA_ASTC_10x8_KHR;if(i===Eh)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_10x10_KHR:r.COMPRESSED_RGBA_ASTC_10x10_KHR;if(i===Th)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x10_KHR:r.COMPRESSED_RGBA_ASTC_12x10_KHR;if(i===Ah)return o===Ft?r.COMPRESSED_SRGB8_ALPHA8_ASTC_12x12_KHR:r.COMPRESSED_RGBA_ASTC_12x12_KHR}else return null;if(i===Rh||i===Ch||i===Ih)if(r=e.get("EXT_texture_compression_bptc"),r!==null){if(i===Rh)return o===Ft?r.COMPRESSED_SRGB_ALPHA_BPTC_UNORM_EXT:r.COMPRESSED_RGBA_BPTC_UNORM_EXT;if(i===Ch)return r.COMPRESSED_RGB_BPTC_SIGNED_FLOAT_EXT;if(i===Ih)return r.COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT_EXT}else return null;if(i===Ph||i===Lh||i===Za||i===Nh)if(r=e.get("EXT_texture_compression_rgtc"),r!==null){if(i===Ph)return r.COMPRESSED_RED_RGTC1_EXT;if(i===Lh)return r.COMPRESSED_SIGNED_RED_RGTC1_EXT;if(i===Za)return r.COMPRESSED_RED_GREEN_RGTC2_EXT;if(i===Nh)return r.COMPRESSED_SIGNED_RED_GREEN_RGTC2_EXT}else return null;return i===Pr?n.UNSIGNED_INT_24_8:n[i]!==void 0?n[i]:null}return{convert:t}}var PE=`
void main() {

	gl_Position = vec4( position, 1.0 );

}`,LE=`
uniform sampler2DArray depthColor;
uniform float depthWidth;
uniform float depthHeight;

void main() {

	vec2 coord = vec2( gl_FragCoord.x / depthWidth, gl_FragCoord.y / depthHeight );

	if ( coord.x >= 1.0 ) {

		gl_FragDepth = texture( depthColor, vec3( coord.x - 1.0, coord.y, 1 ) ).r;

	} else {

		gl_FragDepth = texture( depthColor, vec3( coord.x, coord.y, 0 ) ).r;

	}

}`,wd=class{constructor(){this.texture=null,this.mesh=null,this.depthNear=0,this.depthFar=0}init(e,t){if(this.texture===null){let i=new Ua(e.texture);(e.depthNear!==t.depthNear||e.depthFar!==t.depthFar)&&(this.depthNear=e.depthNear,this.depthFar=e.depthFar),this.texture=i}}getMesh(e){if(this.texture!==null&&this.mesh===null){let t=e.cameras[0].viewport,i=new Qi({vertexShader:PE,fragmentShader:LE,uniforms:{depthColor:{value:this.texture},depthWidth:{value:t.z},depthHeight:{value:t.w}}});this.mesh=new ji(new Oa(20,20),i)}return this.mesh}reset(){this.texture=null,this.mesh=null}getDepthTexture(){return this.texture}},Ed=class extends Di{constructor(e,t){super();let i=this,s=null,r=1,o=null,a="local-floor",l=1,c=null,h=null,f=null,u=null,p=null,g=null,S=typeof XRWebGLBinding<"u",d=new wd,m={},y=t.getContextAttributes(),A=null,b=null,C=[],E=[],x=new ut,T=null,k=null,U=new qn;U.viewport=new sn;let P=new qn;P.viewport=new sn;let B=[U,P],z=new Yc,L=null,H=null;this.cameraAutoUpdate=!0,this.enabled=!1,this.isPresenting=!1,this.getController=function(ee){let pe=C[ee];return pe===void 0&&(pe=new To,C[ee]=pe),pe.getTargetRaySpace()},this.getControllerGrip=function(ee){let pe=C[ee];return pe===void 0&&(pe=new To,C[ee]=pe),pe.getGripSpace()},this.getHand=function(ee){let pe=C[ee];return pe===void 0&&(pe=new To,C[ee]=pe),pe.getHandSpace()};function W(ee){let pe=E.indexOf(ee.inputSource);if(pe===-1)return;let fe=C[pe];fe!==void 0&&(fe.update(ee.inputSource,ee.frame,c||o),fe.dispatchEvent({type:ee.type,data:ee.inputSource}))}function D(){s.removeEventListener("select",W),s.removeEventListener("selectstart",W),s.removeEventListener("selectend",W),s.removeEventListener("squeeze",W),s.removeEventListener("squeezestart",W),s.removeEventListener("squeezeend",W),s.removeEventListener("end",D),s.removeEventListener("inputsourceschange",te);for(let ee=0;ee<C.length;ee++){let pe=E[ee];pe!==null&&(E[ee]=null,C[ee].disconnect(pe))}L=null,H=null,d.reset();for(let ee in m)delete m[ee];if(e.setRenderTarget(A),p=null,u=null,f=null,s=null,b=null,ce.stop(),i.isPresenting=!1,e.setPixelRatio(T),e.setSize(x.width,x.height,!1),k!==null){let ee=k.camera;ee.fov=k.fov,ee.zoom=k.zoom,ee.updateProjectionMatrix(),k=null}i.dispatchEvent({type:"sessionend"})}this.setFramebufferScaleFactor=function(ee){r=ee,i.isPresenting===!0&&Je("WebXRManager: Cannot change framebuffer scale while presenting.")},this.setReferenceSpaceType=function(ee){a=ee,i.isPresenting===!0&&Je("WebXRManager: Cannot change reference space type while presenting.")},this.getReferenceSpace=function(){return c||o},this.setReferenceSpace=function(ee){c=ee},this.getBaseLayer=function(){return u!==null?u:p},this.getBinding=function(){return f===null&&S&&(f=new XRWebGLBinding(s,t)),f},this.getFrame=function(){return g},this.getSession=function(){return s},this.setSession=async function(ee){if(s=ee,s!==null){if(A=e.getRenderTarget(),s.addEventListener("select",W),s.addEventListener("selectstart",W),s.addEventListener("selectend",W),s.addEventListener("squeeze",W),s.addEventListener("squeezestart",W),s.addEventListener("squeezeend",W),s.addEventListener("end",D),s.addEventListener("inputsourceschange",te),y.xrCompatible!==!0&&await t.makeXRCompatible(),T=e.getPixelRatio(),e.getSize(x),S&&"createProjectionLayer"in XRWebGLBinding.prototype){let fe=null,Me=null,ye=null;y.depth&&(ye=y.stencil?t.DEPTH24_STENCIL8:t.DEPTH_COMPONENT24,fe=y.stencil?Es:Ss,Me=y.stencil?Pr:Ui);let qe={colorFormat:t.RGBA8,depthFormat:ye,scaleFactor:r};f=this.getBinding(),u=f.createProjectionLayer(qe),s.updateRenderState({layers:[u]}),e.setPixelRatio(1),e.setSize(u.textureWidth,u.textureHeight,!1),b=new pi(u.textureWidth,u.textureHeight,{format:Bi,type:gi,depthTexture:new Ms(u.textureWidth,u.textureHeight,Me,void 0,void 0,void 0,void 0,void 0,void 0,fe),stencilBuffer:y.stencil,colorSpace:e.outputColorSpace,samples:y.antialias?4:0,resolveDepthBuffer:u.ignoreDepthValues===!1,resolveStencilBuffer:u.ignoreDepthValues===!1,storeMultisampledDepthBuffer:u.ignoreDepthValues===!1,storeMultisampledStencilBuffer:u.ignoreDepthValues===!1})}else{let fe={antialias:y.antialias,alpha:!0,depth:y.depth,stencil:y.stencil,framebufferScaleFactor:r};p=new XRWebGLLayer(s,t,fe),s.updateRenderState({baseLayer:p}),e.setPixelRatio(1),e.setSize(p.framebufferWidth,p.framebufferHeight,!1),b=new pi(p.framebufferWidth,p.framebufferHeight,{format:Bi,type:gi,colorSpace:e.outputColorSpace,stencilBuffer:y.stencil,resolveDepthBuffer:p.ignoreDepthValues===!1,resolveStencilBuffer:p.ignoreDepthValues===!1,storeMultisampledDepthBuffer:p.ignoreDepthValues===!1,storeMultisampledStencilBuffer:p.ignoreDepthValues===!1})}b.isXRRenderTarget=!0,this.setFoveation(l),c=null,o=await s.requestReferenceSpace(a),ce.setContext(s),ce.start(),i.isPresenting=!0,i.dispatchEvent({type:"sessionstart"})}},this.getEnvironmentBlendMode=function(){if(s!==null)return s.environmentBlendMode},this.getDepthTexture=function(){return d.getDepthTexture()};function te(ee){for(let pe=0;pe<ee.removed.length;pe++){let fe=ee.removed[pe],Me=E.indexOf(fe);Me>=0&&(E[Me]=null,C[Me].disconnect(fe))}for(let pe=0;pe<ee.added.length;pe++){let fe=ee.added[pe],Me=E.indexOf(fe);if(Me===-1){for(let qe=0;qe<C.length;qe++)if(qe>=E.length){E.push(fe),Me=qe;break}else if(E[qe]===null){E[qe]=fe,Me=qe;break}if(Me===-1)break}let ye=C[Me];ye&&ye.connect(fe)}}function X(ee,pe){pe===null?ee.matrixWorld.copy(ee.matrix):ee.matrixWorld.multiplyMatrices(pe.matrixWorld,ee.matrix),ee.matrixWorldInverse.copy(ee.matrixWorld).invert()}this.updateCamera=function(ee){if(s===null)return;let pe=ee.near,fe=ee.far;d.texture!==null&&(d.depthNear>0&&(pe=d.depthNear),d.depthFar>0&&(fe=d.depthFar)),z.near=P.near=U.near=pe,z.far=P.far=U.far=fe,(L!==z.near||H!==z.far)&&(s.updateRenderState({depthNear:z.near,depthFar:z.far}),L=z.near,H=z.far),z.layers.mask=ee.layers.mask|6,U.layers.mask=z.layers.mask&-5,P.layers.mask=z.layers.mask&-3;let Me=ee.parent,ye=z.cameras;X(z,Me);for(let qe=0;qe<ye.length;qe++)X(ye[qe],Me);z.projectionMatrix.copy(U.projectionMatrix),z.projectionMatrixInverse.copy(U.projectionMatrixInverse),k===null&&ee.isPerspectiveCamera&&(k={camera:ee,fov:ee.fov,zoom:ee.zoom}),q(ee,z,Me)};function q(ee,pe,fe){fe===null?ee.matrix.copy(pe.matrixWorld):(ee.matrix.copy(fe.matrixWorld),ee.matrix.invert(),ee.matrix.multiply(pe.matrixWorld)),ee.matrix.decompose(ee.position,ee.quaternion,ee.scale),ee.updateMatrixWorld(!0),ee.projectionMatrix.copy(pe.projectionMatrix),ee.projectionMatrixInverse.copy(pe.projectionMatrixInverse),ee.isPerspectiveCamera&&(ee.fov=wo*2*Math.atan(1/ee.projectionMatrix.elements[5]),ee.zoom=1)}this.getCamera=function(){return z},this.getFoveation=function(){if(!(u===null&&p===null))return l},this.setFoveation=function(ee){l=ee,u!==null&&(u.fixedFoveation=ee),p!==null&&p.fixedFoveation!==void 0&&(p.fixedFoveation=ee)},this.hasDepthSensing=function(){return d.texture!==null},this.getDepthSensingMesh=function(){return d.getMesh(z)},this.getCameraTexture=function(ee){return m[ee]};let j=null;function ae(ee,pe){if(h=pe.getViewerPose(c||o),g=pe,h!==null){let fe=h.views;p!==null&&(e.setRenderTargetFramebuffer(b,p.framebuffer),e.setRenderTarget(b));let Me=!1;fe.length!==z.cameras.length&&(z.cameras.length=0,Me=!0);for(let We=0;We<fe.length;We++){let Ce=fe[We],Ne=null;if(p!==null)Ne=p.getViewport(Ce);else{let xt=f.getViewSubImage(u,Ce);Ne=xt.viewport,We===0&&(e.setRenderTargetTextures(b,xt.colorTexture,xt.depthStencilTexture),e.setRenderTarget(b))}let Be=B[We];Be===void 0&&(Be=new qn,Be.layers.enable(We),Be.viewport=new sn,B[We]=Be),Be.matrix.fromArray(Ce.transform.matrix),Be.matrix.decompose(Be.position,Be.quaternion,Be.scale),Be.projectionMatrix.fromArray(Ce.projectionMatrix),Be.projectionMatrixInverse.copy(Be.projectionMatrix).invert(),Be.viewport.set(Ne.x,Ne.y,Ne.width,Ne.height),We===0&&(z.matrix.copy(Be.matrix),z.matrix.decompose(z.position,z.quaternion,z.scale)),Me===!0&&z.cameras.push(Be)}let ye=s.enabledFeatures;if(ye&&ye.includes("depth-sensing")&&s.depthUsage=="gpu-optimized"&&S){f=i.getBinding();let We=f.getDepthInformation(fe[0]);We&&We.isValid&&We.texture&&d.init(We,s.renderState)}if(ye&&ye.includes("camera-access")&&S){e.state.unbindTexture(),f=i.getBinding();for(let We=0;We<fe.length;We++){let Ce=fe[We].camera;if(Ce){let Ne=m[Ce];Ne||(Ne=new Ua,m[Ce]=Ne);let Be=f.getCameraImage(Ce);Ne.sourceTexture=Be}}}}for(let fe=0;fe<C.length;fe++){let Me=E[fe],ye=C[fe];Me!==null&&ye!==void 0&&ye.update(Me,pe,c||o)}j&&j(ee,pe),pe.detectedPlanes&&i.dispatchEvent({type:"planesdetected",data:pe}),g=null}let ce=new j0;ce.setAnimationLoop(ae),this.setAnimationLoop=function(ee){j=ee},this.dispose=function(){}}},NE=new en,l_=new ot;l_.set(-1,0,0,0,1,0,0,0,1);function DE(n,e){function t(d,m){d.matrixAutoUpdate===!0&&d.updateMatrix(),m.value.copy(d.matrix)}function i(d,m){m.color.getRGB(d.fogColor.value,ad(n)),m.isFog?(d.fogNear.value=m.near,d.fogFar.value=m.far):m.isFogExp2&&(d.fogDensity.value=m.density)}function s(d,m,y,A,b){m.isNodeMaterial?m.uniformsNeedUpdate=!1:m.isMeshBasicMaterial?r(d,m):m.isMeshLambertMaterial?(r(d,m),m.envMap&&(d.envMapIntensity.value=m.envMapIntensity)):m.isMeshToonMaterial?(r(d,m),f(d,m)):m.isMeshPhongMaterial?(r(d,m),h(d,m),m.envMap&&(d.envMapIntensity.value=m.envMapIntensity)):m.isMeshStandardMaterial?(r(d,m),u(d,m),m.isMeshPhysicalMaterial&&p(d,m,b)):m.isMeshMatcapMaterial?(r(d,m),g(d,m)):m.isMeshDepthMaterial?r(d,m):m.isMeshDistanceMaterial?(r(d,m),S(d,m)):m.isMeshNormalMaterial?r(d,m):m.isLineBasicMaterial?(o(d,m),m.isLineDashedMaterial&&a(d,m)):m.isPointsMaterial?l(d,m,y,A):m.isSpriteMaterial?c(d,m):m.isShadowMaterial?(d.color.value.copy(m.color),d.opacity.value=m.opacity):m.isShaderMaterial&&(m.uniformsNeedUpdate=!1)}function r(d,m){d.opacity.value=m.opacity,m.color&&d.diffuse.value.copy(m.color),m.emissive&&d.emissive.value.copy(m.emissive).multiplyScalar(m.emissiveIntensity),m.map&&(d.map.value=m.map,t(m.map,d.mapTransform)),m.alphaMap&&(d.alphaMap.value=m.alphaMap,t(m.alphaMap,d.alphaMapTransform)),m.bumpMap&&(d.bumpMap.value=m.bumpMap,t(m.bumpMap,d.bumpMapTransform),d.bumpScale.value=m.bumpScale,m.side===$n&&(d.bumpScale.value*=-1)),m.normalMap&&(d.normalMap.value=m.normalMap,t(m.normalMap,d.normalMapTransform),d.normalScale.value.copy(m.normalScale),m.side===$n&&d.normalScale.value.negate()),m.displacementMap&&(d.displacementMap.value=m.displacementMap,t(m.displacementMap,d.displacementMapTransform),d.displacementScale.value=m.displacementScale,d.displacementBias.value=m.displacementBias),m.emissiveMap&&(d.emissiveMap.value=m.emissiveMap,t(m.emissiveMap,d.emissiveMapTransform)),m.specularMap&&(d.specularMap.value=m.specularMap,t(m.specularMap,d.specularMapTransform)),m.alphaTest>0&&(d.alphaTest.value=m.alphaTest);let y=e.get(m),A=y.envMap,b=y.envMapRotation;A&&(d.envMap.value=A,d.envMapRotation.value.setFromMatrix4(NE.makeRotationFromEuler(b)).transpose(),A.isCubeTexture&&A.isRenderTargetTexture===!1&&d.envMapRotation.value.premultiply(l_),d.reflectivity.value=m.reflectivity,d.ior.value=m.ior,d.refractionRatio.value=m.refractionRatio),m.lightMap&&(d.lightMap.value=m.lightMap,d.lightMapIntensity.value=m.lightMapIntensity,t(m.lightMap,d.lightMapTransform)),m.aoMap&&(d.aoMap.value=m.aoMap,d.aoMapIntensity.value=m.aoMapIntensity,t(m.aoMap,d.aoMapTransform))}function o(d,m){d.diffuse.value.copy(m.color),d.opacity.value=m.opacity,m.map&&(d.map.value=m.map,t(m.map,d.mapTransform))}function a(d,m){d.dashSize.value=m.dashSize,d.totalSize.value=m.dashSize+m.gapSize,d.scale.value=m.scale}function l(d,m,y,A){d.diffuse.value.copy(m.color),d.opacity.value=m.opacity,d.size.value=m.size*y,d.scale.value=A*.5,m.map&&(d.map.value=m.map,t(m.map,d.uvTransform)),m.alphaMap&&(d.alphaMap.value=m.alphaMap,t(m.alphaMap,d.alphaMapTransform)),m.alphaTest>0&&(d.alphaTest.value=m.alphaTest)}function c(d,m){d.diffuse.value.copy(m.color),d.opacity.value=m.opacity,d.rotation.value=m.rotation,m.map&&(d.map.value=m.map,t(m.map,d.mapTransform)),m.alphaMap&&(d.alphaMap.value=m.alphaMap,t(m.alphaMap,d.alphaMapTransform)),m.alphaTest>0&&(d.alphaTest.value=m.alphaTest)}function h(d,m){d.specular.value.copy(m.specular),d.shininess.value=Math.max(m.shininess,1e-4)}function f(d,m){m.gradientMap&&(d.gradientMap.value=m.gradientMap)}function u(d,m){d.metalness.value=m.metalness,m.metalnessMap&&(d.metalnessMap.value=m.metalnessMap,t(m.metalnessMap,d.metalnessMapTransform)),d.roughness.value=m.roughness,m.roughnessMap&&(d.roughnessMap.value=m.roughnessMap,t(m.roughnessMap,d.roughnessMapTransform)),m.envMap&&(d.envMapIntensity.value=m.envMapIntensity)}function p(d,m,y){d.ior.value=m.ior,m.diffuseRoughness>0&&(d.diffuseRoughness.value=m.diffuseRoughness,m.diffuseRoughnessMap&&(d.diffuseRoughnessMap.value=m.diffuseRoughnessMap,t(m.diffuseRoughnessMap,d.diffuseRoughnessMapTransform))),m.sheen>0&&(d.sheenColor.value.copy(m.sheenColor).multiplyScalar(m.sheen),d.sheenRoughness.value=m.sheenRoughness,m.sheenColorMap&&(d.sheenColorMap.value=m.sheenColorMap,t(m.sheenColorMap,d.sheenColorMapTransform)),m.sheenRoughnessMap&&(d.sheenRoughnessMap.value=m.sheenRoughnessMap,t(m.sheenRoughnessMap,d.sheenRoughnessMapTransform))),m.clearcoat>0&&(d.clearcoat.value=m.clearcoat,d.clearcoatRoughness.value=m.clearcoatRoughness,m.clearcoatMap&&(d.clearcoatMap.value=m.clearcoatMap,t(m.clearcoatMap,d.clearcoatMapTransform)),m.clearcoatRoughnessMap&&(d.clearcoatRoughnessMap.value=m.clearcoatRoughnessMap,t(m.clearcoatRoughnessMap,d.clearcoatRoughnessMapTransform)),m.clearcoatNormalMap&&(d.clearcoatNormalMap.value=m.clearcoatNormalMap,t(m.clearcoatNormalMap,d.clearcoatNormalMapTransform),d.clearcoatNormalScale.value.copy(m.clearcoatNormalScale),m.side===$n&&d.clearcoatNormalScale.value.negate())),m.dispersion>0&&(d.dispersion.value=m.dispersion),m.retroreflectivity>0&&(d.retroreflectivity.value=m.retroreflectivity),m.iridescence>0&&(d.iridescence.value=m.iridescence,d.iridescenceIOR.value=m.iridescenceIOR,d.iridescenceThicknessMinimum.value=m.iridescenceThicknessMinimum,d.iridescenceThicknessMaximum.value=m.iridescenceThicknessMaximum,m.iridescenceMap&&(d.iridescenceMap.value=m.iridescenceMap,t(m.iridescenceMap,d.iridescenceMapTransform)),m.iridescenceThicknessMap&&(d.iridescenceThicknessMap.value=m.iridescenceThicknessMap,t(m.iridescenceThicknessMap,d.iridescenceThicknessMapTransform))),m.transmission>0&&(d.transmission.value=m.transmission,d.transmissionSamplerMap.value=y.texture,d.transmissionSamplerSize.value.set(y.width,y.height),m.transmissionMap&&(d.transmissionMap.value=m.transmissionMap,t(m.transmissionMap,d.transmissionMapTransform)),d.thickness.value=m.thickness,m.thicknessMap&&(d.thicknessMap.value=m.thicknessMap,t(m.thicknessMap,d.thicknessMapTransform)),d.attenuationDistance.value=m.attenuationDistance,d.attenuationColor.value.copy(m.attenuationColor)),m.anisotropy>0&&(d.anisotropyVector.value.set(m.anisotropy*Math.cos(m.anisotropyRotation),m.anisotropy*Math.sin(m.anisotropyRotation)),m.anisotropyMap&&(d.anisotropyMap.value=m.anisotropyMap,t(m.anisotropyMap,d.anisotropyMapTransform))),d.specularIntensity.value=m.specularIntensity,d.specularColor.value.copy(m.specularColor),m.specularColorMap&&(d.specularColorMap.value=m.specularColorMap,t(m.specularColorMap,d.specularColorMapTransform)),m.specularIntensityMap&&(d.specularIntensityMap.value=m.specularIntensityMap,t(m.specularIntensityMap,d.specularIntensityMapTransform))}function g(d,m){m.matcap&&(d.matcap.value=m.matcap)}function S(d,m){let y=e.get(m).light;d.referencePosition.value.setFromMatrixPosition(y.matrixWorld),d.nearDistance.value=y.shadow.camera.near,d.farDistance.value=y.shadow.camera.far}return{refreshFogUniforms:i,refreshMaterialUniforms:s}}function UE(n,e,t,i){let s={},r={};function o(y,A){let b=A.program;i.uniformBlockBinding(y,b,s[y.id])}function a(y,A){let b=s[y.id];b===void 0&&(g(y),b=l(y),s[y.id]=b,y.addEventListener("dispose",d));let C=A.program;i.updateUBOMapping(y,C);let E=e.render.frame;r[y.id]!==E&&(c(y),r[y.id]=E)}function l(y){let A=n.createBuffer(),b=y.__size,C=y.usage;return n.bindBuffer(n.UNIFORM_BUFFER,A),n.bufferData(n.UNIFORM_BUFFER,b,C),n.bindBuffer(n.UNIFORM_BUFFER,null),A}function c(y){let A=s[y.id],b=y.uniforms,C=y.__cache;n.bindBuffer(n.UNIFORM_BUFFER,A);for(let E=0,x=b.length;E<x;E++){let T=b[E];if(Array.isArray(T))for(let k=0,U=T.length;k<U;k++)h(T[k],E,k,C);else h(T,E,0,C)}n.bindBuffer(n.UNIFORM_BUFFER,null)}function h(y,A,b,C){if(u(y,A,b,C)===!0){let E=y.__offset,x=y.value;if(Array.isArray(x)){let T=0;for(let k=0;k<x.length;k++){let U=x[k],P=S(U,!0);f(U,y.__data,T),T+=P.storage/Float32Array.BYTES_PER_ELEMENT}}else f(x,y.__data,0);n.bufferSubData(n.UNIFORM_BUFFER,E,y.__data)}}function f(y,A,b){typeof y=="number"||typeof y=="boolean"?A[b]=y:y.isMatrix3?(A[b]=y.elements[0],A[b+1]=y.elements[1],A[b+2]=y.elements[2],A[b+3]=0,A[b+4]=y.elements[3],A[b+5]=y.elements[4],A[b+6]=y.elements[5],A[b+7]=0,A[b+8]=y.elements[6],A[b+9]=y.elements[7],A[b+10]=y.elements[8],A[b+11]=0):ArrayBuffer.isView(y)?A.set(y.subarray(0,A.length-b),b):y.toArray(A,b)}function u(y,A,b,C){let E=y.value,x=A+"_"+b;if(Array.isArray(E)){C[x]===void 0&&(C[x]=[]);let T=C[x],k=!1;for(let U=0;U<E.length;U++)p(E[U],T,U)===!0&&(k=!0);return k}return p(E,C,x)}function p(y,A,b){if(A[b]===void 0)return typeof y=="number"||typeof y=="boolean"?A[b]=y:ArrayBuffer.isView(y)?A[b]=y.slice():A[b]=y.clone(),!0;{let C=A[b];if(typeof y=="number"||typeof y=="boolean"){if(C!==y)return A[b]=y,!0}else{if(ArrayBuffer.isView(y))return!0;if(C.equals(y)===!1)return C.copy(y),!0}}return!1}function g(y){let A=y.uniforms,b=0,C=16;for(let x=0,T=A.length;x<T;x++){let k=Array.isArray(A[x])?A[x]:[A[x]];for(let U=0,P=k.length;U<P;U++){let B=k[U],z=Array.isArray(B.value)?B.value:[B.value],L=Array.isArray(A[x])||Array.isArray(B.value),H=b;for(let D=0,te=z.length;D<te;D++){let X=z[D],q=S(X,L),j=b%C,ae=j%q.boundary,ce=j+ae;b+=ae,ce!==0&&C-ce<q.storage&&(b+=C-ce),D===0&&(H=b),b+=q.storage}let W=B.type==="int"?Int32Array:B.type==="uint"?Uint32Array:Float32Array;B.__data=new W((b-H)/Float32Array.BYTES_PER_ELEMENT),B.__offset=H}}let E=b%C;return E>0&&(b+=C-E),y.__size=b,y.__cache={},this}function S(y,A){let b={boundary:0,storage:0};return typeof y=="number"||typeof y=="boolean"?(b.boundary=4,b.storage=4):y.isVector2?(b.boundary=8,b.storage=8):y.isVector3||y.isColor?(b.boundary=16,b.storage=12):y.isVector4?(b.boundary=16,b.storage=16):y.isMatrix3?(b.boundary=16,b.storage=48):y.isMatrix4?(b.boundary=16,b.storage=64):y.isTexture?Je("WebGLRenderer: Texture samplers can not be part of an uniforms group."):ArrayBuffer.isView(y)?(b.boundary=16,b.storage=y.byteLength):Je("WebGLRenderer: Unsupported uniform value type.",y),A===!0&&(b.boundary=16,b.storage=Math.ceil(b.storage/16)*16),b}function d(y){let A=y.target;A.removeEventListener("dispose",d),n.deleteBuffer(s[A.id]),delete s[A.id],delete r[A.id]}function m(){for(let y in s)n.deleteBuffer(s[y]);s={},r={}}return{bind:o,update:a,dispose:m}}var OE=new Uint16Array([12469,15057,12620,14925,13266,14620,13807,14376,14323,13990,14545,13625,14713,13328,14840,12882,14931,12528,14996,12233,15039,11829,15066,11525,15080,11295,15085,10976,15082,10705,15073,10495,13880,14564,13898,14542,13977,14430,14158,14124,14393,13732,14556,13410,14702,12996,14814,12596,14891,12291,14937,11834,14957,11489,14958,11194,14943,10803,14921,10506,14893,10278,14858,9960,14484,14039,14487,14025,14499,13941,14524,13740,14574,13468,14654,13106,14743,12678,14818,12344,14867,11893,14889,11509,14893,11180,14881,10751,14852,10428,14812,10128,14765,9754,14712,9466,14764,13480,14764,13475,14766,13440,14766,13347,14769,13070,14786,12713,14816,12387,14844,11957,14860,11549,14868,11215,14855,10751,14825,10403,14782,10044,14729,9651,14666,9352,14599,9029,14967,12835,14966,12831,14963,12804,14954,12723,14936,12564,14917,12347,14900,11958,14886,11569,14878,11247,14859,10765,14828,10401,14784,10011,14727,9600,14660,9289,14586,8893,14508,8533,15111,12234,15110,12234,15104,12216,15092,12156,15067,12010,15028,11776,14981,11500,14942,11205,14902,10752,14861,10393,14812,9991,14752,9570,14682,9252,14603,8808,14519,8445,14431,8145,15209,11449,15208,11451,15202,11451,15190,11438,15163,11384,15117,11274,15055,10979,14994,10648,14932,10343,14871,9936,14803,9532,14729,9218,14645,8742,14556,8381,14461,8020,14365,7603,15273,10603,15272,10607,15267,10619,15256,10631,15231,10614,15182,10535,15118,10389,15042,10167,14963,9787,14883,9447,14800,9115,14710,8665,14615,8318,14514,7911,14411,7507,14279,7198,15314,9675,15313,9683,15309,9712,15298,9759,15277,9797,15229,9773,15166,9668,15084,9487,14995,9274,14898,8910,14800,8539,14697,8234,14590,7790,14479,7409,14367,7067,14178,6621,15337,8619,15337,8631,15333,8677,15325,8769,15305,8871,15264,8940,15202,8909,15119,8775,15022,8565,14916,8328,14804,8009,14688,7614,14569,7287,14448,6888,14321,6483,14088,6171,15350,7402,15350,7419,15347,7480,15340,7613,15322,7804,15287,7973,15229,8057,15148,8012,15046,7846,14933,7611,14810,7357,14682,7069,14552,6656,14421,6316,14251,5948,14007,5528,15356,5942,15356,5977,15353,6119,15348,6294,15332,6551,15302,6824,15249,7044,15171,7122,15070,7050,14949,6861,14818,6611,14679,6349,14538,6067,14398,5651,14189,5311,13935,4958,15359,4123,15359,4153,15356,4296,15353,4646,15338,5160,15311,5508,15263,5829,15188,6042,15088,6094,14966,6001,14826,5796,14678,5543,14527,5287,14377,4985,14133,4586,13869,4257,15360,1563,15360,1642,15358,2076,15354,2636,15341,3350,15317,4019,15273,4429,15203,4732,15105,4911,14981,4932,14836,4818,14679,4621,14517,4386,14359,4156,14083,3795,13808,3437,15360,122,15360,137,15358,285,15355,636,15344,1274,15322,2177,15281,2765,15215,3223,15120,3451,14995,3569,14846,3567,14681,3466,14511,3305,14344,3121,14037,2800,13753,2467,15360,0,15360,1,15359,21,15355,89,15346,253,15325,479,15287,796,15225,1148,15133,1492,15008,1749,14856,1882,14685,1886,14506,1783,14324,1608,13996,1398,13702,1183]),ns=null;function FE(){return ns===null&&(ns=new Rc(OE,16,16,or,Fi),ns.name="DFG_LUT",ns.minFilter=Yn,ns.magFilter=Yn,ns.wrapS=Ji,ns.wrapT=Ji,ns.generateMipmaps=!1,ns.needsUpdate=!0),ns}var Fh=class{constructor(e={}){let{canvas:t=S0(),context:i=null,depth:s=!0,stencil:r=!1,alpha:o=!1,antialias:a=!1,premultipliedAlpha:l=!0,preserveDrawingBuffer:c=!1,powerPreference:h="default",failIfMajorPerformanceCaveat:f=!1,reversedDepthBuffer:u=!1,outputBufferType:p=gi}=e;this.isWebGLRenderer=!0;let g;if(i!==null){if(typeof WebGLRenderingContext<"u"&&i instanceof WebGLRenderingContext)throw new Error("THREE.WebGLRenderer: WebGL 1 is not supported since r163.");g=i.getContextAttributes().alpha}else g=o;let S=p,d=new Set([ih,nh,th]),m=new Set([gi,Ui,Uo,Pr,Qc,eh]),y=new Uint32Array(4),A=new Int32Array(4),b={textures:[],min:[],max:[],resolution:[]},C=null,E=null,x=[],T=[],k=null;this.domElement=t,this.debug={checkShaderErrors:!0,diagnostics:{keywords:!1},onShaderError:null},this.autoClear=!0,this.autoClearColor=!0,this.autoClearDepth=!0,this.autoClearStencil=!0,this.sortObjects=!0,this.clippingPlanes=[],this.localClippingEnabled=!1,this.toneMapping=ts,this.toneMappingExposure=1,this.transmissionResolutionScale=1;let U=this,P=!1,B=null,z=null,L=null,H=null;this._outputColorSpace=hi;let W=0,D=0,te=null,X=-1,q=null,j=new sn,ae=new sn,ce=null,ee=new gt(0),pe=0,fe=t.width,Me=t.height,ye=1,qe=null,it=null,We=new sn(0,0,fe,Me),Ce=new sn(0,0,fe,Me),Ne=!1,Be=new Ar,xt=new Cc,Rt=!1,Bt=!1,at=new en,Ct=new K,Ze=new sn,ft={background:null,fog:null,environment:null,overrideMaterial:null,isScene:!0},pt=!1;function bt(){return te===null?ye:1}let O=i;function Pe(w,G){return t.getContext(w,G)}let je,ht,Ee,Vt,Xe,Ke,R,v,Y,ue,oe,ve,Se,ne,se,me,F,re,ie,Te,xe,we,Ye;try{let w={alpha:!0,depth:s,stencil:r,antialias:a,premultipliedAlpha:l,preserveDrawingBuffer:c,powerPreference:h,failIfMajorPerformanceCaveat:f};if("setAttribute"in t&&t.setAttribute("data-engine",`three.js r${"187"}`),t.addEventListener("webglcontextlost",Ge,!1),t.addEventListener("webglcontextrestored",nt,!1),t.addEventListener("webglcontextcreationerror",Ie,!1),O===null){let G="webgl2";if(O=Pe(G,w),O===null)throw Pe(G)?new Error("THREE.WebGLRenderer: Error creating WebGL context with your selected attributes."):new Error("THREE.WebGLRenderer: Error creating WebGL context.")}tt()}catch(w){throw t.removeEventListener("webglcontextlost",Ge,!1),t.removeEventListener("webglcontextrestored",nt,!1),t.removeEventListener("webglcontextcreationerror",Ie,!1),rt("WebGLRenderer: "+w.message),w}function tt(){je=new $M(O),je.init(),xe=new IE(O,je),ht=new FM(O,je,e,xe),Ee=new RE(O,je),ht.reversedDepthBuffer&&u&&Ee.buffers.depth.setReversed(!0),z=O.createFramebuffer(),L=O.createFramebuffer(),H=O.createFramebuffer(),Vt=new JM(O),Xe=new pE,Ke=new CE(O,je,Ee,Xe,ht,xe,Vt),R=new YM(U),v=new Qv(O),we=new UM(O,v),Y=new ZM(O,v,Vt,we),ue=new QM(O,Y,v,we,Vt),re=new jM(O,ht,Ke),se=new BM(Xe),oe=new dE(U,R,je,ht,we,se),ve=new DE(U,Xe),Se=new gE,ne=new bE(je),F=new DM(U,R,Ee,ue,g,l),me=new AE(U,ue,ht),Ye=new UE(O,Vt,ht,Ee),ie=new OM(O,je,Vt),Te=new KM(O,je,Vt),Vt.programs=oe.programs,U.capabilities=ht,U.extensions=je,U.properties=Xe,U.renderLists=Se,U.shadowMap=me,U.state=Ee,U.info=Vt}S!==gi&&(k=new tw(S,t.width,t.height,a,s,r));let he=new Ed(U,O);this.xr=he,this.getContext=function(){return O},this.getContextAttributes=function(){return O.getContextAttributes()},this.forceContextLoss=function(){let w=je.get("WEBGL_lose_context");w&&w.loseContext()},this.forceContextRestore=function(){let w=je.get("WEBGL_lose_context");w&&w.restoreContext()},this.getPixelRatio=function(){return ye},this.setPixelRatio=function(w){w!==void 0&&(ye=w,this.setSize(fe,Me,!1))},this.getSize=function(w){return w.set(fe,Me)},this.setSize=function(w,G,Q=!0){if(he.isPresenting){Je("WebGLRenderer: Can't change size while VR device is presenting.");return}fe=w,Me=G,t.width=Math.floor(w*ye),t.height=Math.floor(G*ye),Q===!0&&(t.style.width=w+"px",t.style.height=G+"px"),k!==null&&k.setSize(t.width,t.height),this.setViewport(0,0,w,G)},this.getDrawingBufferSize=function(w){return w.set(fe*ye,Me*ye).floor()},this.setDrawingBufferSize=function(w,G,Q){fe=w,Me=G,ye=Q,t.width=Math.floor(w*Q),t.height=Math.floor(G*Q),this.setViewport(0,0,w,G)},this.setEffects=function(w){if(S===gi){rt("WebGLRenderer: setEffects() requires outputBufferType set to HalfFloatType or FloatType.");return}if(w){for(let G=0;G<w.length;G++)if(w[G].isOutputPass===!0){Je("WebGLRenderer: OutputPass is not needed in setEffects(). Tone mapping and color space conversion are applied automatically.");break}}k.setEffects(w||[])},this.getCurrentViewport=function(w){return w.copy(j)},this.getViewport=function(w){return w.copy(We)},this.setViewport=function(w,G,Q,$){w.isVector4?We.set(w.x,w.y,w.z,w.w):We.set(w,G,Q,$),Ee.viewport(j.copy(We).multiplyScalar(bt()).round())},this.getScissor=function(w){return w.copy(Ce)},this.setScissor=function(w,G,Q,$){w.isVector4?Ce.set(w.x,w.y,w.z,w.w):Ce.set(w,G,Q,$),Ee.scissor(ae.copy(Ce).multiplyScalar(bt()).round())},this.getScissorTest=function(){return Ne},this.setScissorTest=function(w){Ee.setScissorTest(Ne=w)},this.setOpaqueSort=function(w){qe=w},this.setTransparentSort=function(w){it=w},this.getClearColor=function(w){return w.copy(F.getClearColor())},this.setClearColor=function(){F.setClearColor(...arguments)},this.getClearAlpha=function(){return F.getClearAlpha()},this.setClearAlpha=function(){F.setClearAlpha(...arguments)},this.clear=function(w=!0,G=!0,Q=!0){let $=0;if(w){let Z=!1;if(te!==null){let Ae=te.texture.format;Z=d.has(Ae)}if(Z){let Ae=te.texture.type,Le=m.has(Ae),Re=F.getClearColor(),De=F.getClearAlpha(),Ve=Re.r,st=Re.g,yt=Re.b;Le?(y[0]=Ve,y[1]=st,y[2]=yt,y[3]=De,O.clearBufferuiv(O.COLOR,0,y)):(A[0]=Ve,A[1]=st,A[2]=yt,A[3]=De,O.clearBufferiv(O.COLOR,0,A))}else $|=O.COLOR_BUFFER_BIT}G&&($|=O.DEPTH_BUFFER_BIT,this.state.buffers.depth.setMask(!0)),Q&&($|=O.STENCIL_BUFFER_BIT,this.state.buffers.stencil.setMask(4294967295)),$!==0&&O.clear($)},this.clearColor=function(){this.clear(!0,!1,!1)},this.clearDepth=function(){this.clear(!1,!0,!1)},this.clearStencil=function(){this.clear(!1,!1,!0)},this.setNodesHandler=function(w){w.setRenderer(this),B=w},this.dispose=function(){t.removeEventListener("webglcontextlost",Ge,!1),t.removeEventListener("webglcontextrestored",nt,!1),t.removeEventListener("webglcontextcreationerror",Ie,!1),F.dispose(),Se.dispose(),ne.dispose(),Ke.dispose(),Xe.dispose(),R.dispose(),ue.dispose(),Y.dispose(),we.dispose(),Ye.dispose(),oe.dispose(),he.dispose(),he.removeEventListener("sessionstart",el),he.removeEventListener("sessionend",zi),ss.stop()};function Ge(w){w.preventDefault(),nd("WebGLRenderer: Context Lost."),P=!0}function nt(){nd("WebGLRenderer: Context Restored."),P=!1;let w=Vt.autoReset,G=me.enabled,Q=me.autoUpdate,$=me.needsUpdate,Z=me.type;tt(),Vt.autoReset=w,me.enabled=G,me.autoUpdate=Q,me.needsUpdate=$,me.type=Z}function Ie(w){rt("WebGLRenderer: A WebGL context could not be created. Reason: ",w.statusMessage)}function dt(w){let G=w.target;G.removeEventListener("dispose",dt),qt(G)}function qt(w){zn(w),Xe.remove(w)}function zn(w){let G=Xe.get(w).programs;G!==void 0&&(G.forEach(function(Q){oe.releaseProgram(Q)}),w.isShaderMaterial&&oe.releaseShaderCache(w))}this.renderBufferDirect=function(w,G,Q,$,Z,Ae){G===null&&(G=ft);let Le=Z.isMesh&&Z.matrixWorld.determinantAffine()<0,Re=Ho(w,G,Q,$,Z);Ee.setMaterial($,Le);let De=Q.index,Ve=1;if($.wireframe===!0){if(De=Y.getWireframeAttribute(Q),De===void 0)return;Ve=2}let st=Q.drawRange,yt=Q.attributes.position,He=st.start*Ve,vt=(st.start+st.count)*Ve;Ae!==null&&(He=Math.max(He,Ae.start*Ve),vt=Math.min(vt,(Ae.start+Ae.count)*Ve)),De!==null?(He=Math.max(He,0),vt=Math.min(vt,De.count)):yt!=null&&(He=Math.max(He,0),vt=Math.min(vt,yt.count));let tn=vt-He;if(tn<0||tn===1/0)return;we.setup(Z,$,Re,Q,De);let kt,zt=ie;if(De!==null&&(kt=v.get(De),zt=Te,zt.setIndex(kt)),Z.isMesh)$.wireframe===!0?(Ee.setLineWidth($.wireframeLinewidth*bt()),zt.setMode(O.LINES)):zt.setMode(O.TRIANGLES);else if(Z.isLine){let yn=$.linewidth;yn===void 0&&(yn=1),Ee.setLineWidth(yn*bt()),Z.isLineSegments?zt.setMode(O.LINES):Z.isLineLoop?zt.setMode(O.LINE_LOOP):zt.setMode(O.LINE_STRIP)}else Z.isPoints?zt.setMode(O.POINTS):Z.isSprite&&zt.setMode(O.TRIANGLES);if(Z.isBatchedMesh)if(je.get("WEBGL_multi_draw"))zt.renderMultiDraw(Z._multiDrawStarts,Z._multiDrawCounts,Z._multiDrawCount);else{let yn=Z._multiDrawStarts,ke=Z._multiDrawCounts,fn=Z._multiDrawCount,Et=De?v.get(De).bytesPerElement:1,os=Xe.get($).currentProgram.getUniforms();for(let dn=0;dn<fn;dn++)os.setValue(O,"_gl_DrawID",dn),zt.render(yn[dn]/Et,ke[dn])}else if(Z.isInstancedMesh)zt.renderInstances(He,tn,Z.count);else if(Q.isInstancedBufferGeometry){let yn=Q._maxInstanceCount!==void 0?Q._maxInstanceCount:1/0,ke=Math.min(Q.instanceCount,yn);zt.renderInstances(He,tn,ke)}else zt.render(He,tn)};function ko(w,G,Q,$){B!==null&&w.isNodeMaterial&&B.setObject($,w),Rt===!0&&se.setState(w,Q,!1),w.transparent===!0&&w.side===es&&w.forceSinglePass===!1?(w.side=$n,w.needsUpdate=!0,Gi(w,G,$),w.side=rr,w.needsUpdate=!0,Gi(w,G,$),w.side=es):Gi(w,G,$)}this.compile=function(w,G,Q=null){Q===null&&(Q=w),B!==null&&B.renderStart(w,G,Q),E=ne.get(Q),E.init(G),T.push(E),Q.traverseVisible(function(Z){Z.isLight&&Z.layers.test(G.layers)&&(E.pushLight(Z),Z.castShadow&&E.pushShadow(Z))}),w!==Q&&w.traverseVisible(function(Z){Z.isLight&&Z.layers.test(G.layers)&&(E.pushLight(Z),Z.castShadow&&E.pushShadow(Z))}),E.setupLights(),B!==null&&B.updateLights(E.state.lightsArray),Bt=this.localClippingEnabled,Rt=se.init(this.clippingPlanes,Bt),Rt===!0&&se.setGlobalState(this.clippingPlanes,G),B!==null&&me.render(E.state.shadowsArray,Q,G);let $=new Set;return w.traverse(function(Z){if(!(Z.isMesh||Z.isPoints||Z.isLine||Z.isSprite))return;let Ae=Z.material;if(Ae)if(Array.isArray(Ae))for(let Le=0;Le<Ae.length;Le++){let Re=Ae[Le];ko(Re,Q,G,Z),$.add(Re)}else ko(Ae,Q,G,Z),$.add(Ae)}),E=T.pop(),B!==null&&B.renderEnd(),$},this.compileAsync=function(w,G,Q=null){let $=this.compile(w,G,Q);return new Promise(Z=>{function Ae(){if($.forEach(function(Le){let De=Xe.get(Le).currentProgram;(De===void 0||De.isReady())&&$.delete(Le)}),$.size===0){Z(w);return}setTimeout(Ae,10)}je.get("KHR_parallel_shader_compile")!==null?Ae():setTimeout(Ae,10)})};let Dr=null;function Yh(w){Dr&&Dr(w)}function el(){ss.stop()}function zi(){ss.start()}let ss=new j0;ss.setAnimationLoop(Yh),typeof self<"u"&&ss.setContext(self),this.setAnimationLoop=function(w){Dr=w,he.setAnimationLoop(w),w===null?ss.stop():ss.start()},he.addEventListener("sessionstart",el),he.addEventListener("sessionend",zi),this.render=function(w,G){if(G!==void 0&&G.isCamera!==!0){rt("WebGLRenderer.render: camera is not an instance of THREE.Camera.");return}if(P===!0)return;B!==null&&B.renderStart(w,G);let Q=he.enabled===!0&&he.isPresenting===!0,$=k!==null&&(te===null||Q)&&k.begin(U,te);if(w.matrixWorldAutoUpdate===!0&&w.updateMatrixWorld(),G.parent===null&&G.matrixWorldAutoUpdate===!0&&G.updateMatrixWorld(),he.enabled===!0&&he.isPresenting===!0&&(k===null||k.isCompositing()===!1)&&(he.cameraAutoUpdate===!0&&he.updateCamera(G),G=he.getCamera()),w.isScene===!0&&w.onBeforeRender(U,w,G,te),E=ne.get(w,T.length),E.init(G),E.state.textureUnits=Ke.getTextureUnits(),T.push(E),at.multiplyMatrices(G.projectionMatrix,G.matrixWorldInverse),G.isArrayCamera?xt.setFromArrayCamera(G):Be.setFromProjectionMatrix(at,Mi,G.reversedDepth),Bt=this.localClippingEnabled,Rt=se.init(this.clippingPlanes,Bt),C=Se.get(w,x.length),C.init(),x.push(C),this.info.render.frame++,he.enabled===!0&&he.isPresenting===!0){let Le=U.xr.getDepthSensingMesh();Le!==null&&rs(Le,G,-1/0,U.sortObjects)}rs(w,G,0,U.sortObjects),C.finish(),B!==null&&B.updateLights(E.state.lightsArray),U.sortObjects===!0&&C.sort(qe,it),pt=he.enabled===!1||he.isPresenting===!1||he.hasDepthSensing()===!1,pt&&F.addToRenderList(C,w),this.info.autoReset===!0&&this.info.reset(),Rt===!0&&se.beginShadows();let Z=E.state.shadowsArray;if(me.render(Z,w,G),Rt===!0&&se.endShadows(),($&&k.hasRenderPass())===!1){let Le=C.opaque,Re=C.transmissive;if(E.setupLights(),G.isArrayCamera){let De=G.cameras;if(Re.length>0)for(let Ve=0,st=De.length;Ve<st;Ve++){let yt=De[Ve];wi(Le,Re,w,yt)}pt&&F.render(w);for(let Ve=0,st=De.length;Ve<st;Ve++){let yt=De[Ve];zo(C,w,yt,yt.viewport)}}else Re.length>0&&wi(Le,Re,w,G),pt&&F.render(w),zo(C,w,G)}te!==null&&D===0&&(Ke.updateMultisampleRenderTarget(te),Ke.updateRenderTargetMipmap(te)),$&&k.end(U),w.isScene===!0&&w.onAfterRender(U,w,G),we.resetDefaultState(),X=-1,q=null,T.pop(),T.length>0?(E=T[T.length-1],Ke.setTextureUnits(E.state.textureUnits),Rt===!0&&se.setGlobalState(U.clippingPlanes,E.state.camera)):E=null,x.pop(),x.length>0?C=x[x.length-1]:C=null,B!==null&&B.renderEnd()};function rs(w,G,Q,$){if(w.visible===!1)return;if(w.layers.test(G.layers)){if(w.isGroup)Q=w.renderOrder;else if(w.isLOD)w.autoUpdate===!0&&w.update(G);else if(w.isLight)E.pushLight(w),w.castShadow&&E.pushShadow(w);else if(w.isSprite){let Le=G.isArrayCamera?xt:Be;if(!w.frustumCulled||w.intersectsFrustum(Le)){$&&Ze.setFromMatrixPosition(w.matrixWorld).applyMatrix4(at);let Re=ue.update(w),De=w.material;De.visible&&C.push(w,Re,De,Q,Ze.z,null,G)}}else if(w.isMesh||w.isLine||w.isPoints){let Le=G.isArrayCamera?xt:Be;if(!w.frustumCulled||w.intersectsFrustum(Le)){let Re=ue.update(w),De=w.material;if($&&(w.boundingSphere!==void 0?(w.boundingSphere===null&&w.computeBoundingSphere(),Ze.copy(w.boundingSphere.center)):(Re.boundingSphere===null&&Re.computeBoundingSphere(),Ze.copy(Re.boundingSphere.center)),Ze.applyMatrix4(w.matrixWorld).applyMatrix4(at)),Array.isArray(De)){let Ve=Re.groups;for(let st=0,yt=Ve.length;st<yt;st++){let He=Ve[st],vt=De[He.materialIndex];vt&&vt.visible&&C.push(w,Re,vt,Q,Ze.z,He,G)}}else De.visible&&C.push(w,Re,De,Q,Ze.z,null,G)}}}let Ae=w.children;for(let Le=0,Re=Ae.length;Le<Re;Le++)rs(Ae[Le],G,Q,$)}function zo(w,G,Q,$){let{opaque:Z,transmissive:Ae,transparent:Le}=w;E.setupLightsView(Q),Rt===!0&&se.setGlobalState(U.clippingPlanes,Q),$&&Ee.viewport(j.copy($)),Z.length>0&&rn(Z,G,Q),Ae.length>0&&rn(Ae,G,Q),Le.length>0&&rn(Le,G,Q),Ee.buffers.depth.setTest(!0),Ee.buffers.depth.setMask(!0),Ee.buffers.color.setMask(!0),Ee.setPolygonOffset(!1)}function wi(w,G,Q,$){if((Q.isScene===!0?Q.overrideMaterial:null)!==null)return;if(E.state.transmissionRenderTarget[$.id]===void 0){let He=je.has("EXT_color_buffer_half_float")||je.has("EXT_color_buffer_float");E.state.transmissionRenderTarget[$.id]=new pi(1,1,{generateMipmaps:!0,type:He?Fi:gi,minFilter:ws,samples:Math.max(4,ht.samples),stencilBuffer:r,resolveDepthBuffer:!1,resolveStencilBuffer:!1,storeMultisampledDepthBuffer:!1,storeMultisampledStencilBuffer:!1,colorSpace:At.workingColorSpace})}let Ae=E.state.transmissionRenderTarget[$.id],Le=$.viewport||j;Ae.setSize(Le.z*U.transmissionResolutionScale,Le.w*U.transmissionResolutionScale);let Re=U.getRenderTarget(),De=U.getActiveCubeFace(),Ve=U.getActiveMipmapLevel();U.setRenderTarget(Ae),U.getClearColor(ee),pe=U.getClearAlpha(),pe<1&&U.setClearColor(16777215,.5),U.clear(),pt&&F.render(Q);let st=U.toneMapping;U.toneMapping=ts;let yt=$.viewport;if($.viewport!==void 0&&($.viewport=void 0),E.setupLightsView($),Rt===!0&&se.setGlobalState(U.clippingPlanes,$),rn(w,Q,$),Ke.updateMultisampleRenderTarget(Ae),Ke.updateRenderTargetMipmap(Ae),je.has("WEBGL_multisampled_render_to_texture")===!1){let He=!1;for(let vt=0,tn=G.length;vt<tn;vt++){let kt=G[vt],{object:zt,geometry:yn,material:ke,group:fn}=kt;if(ke.side===es&&zt.layers.test($.layers)){let Et=ke.side;ke.side=$n,ke.needsUpdate=!0,cn(zt,Q,$,yn,ke,fn),ke.side=Et,ke.needsUpdate=!0,He=!0}}He===!0&&(Ke.updateMultisampleRenderTarget(Ae),Ke.updateRenderTargetMipmap(Ae))}U.setRenderTarget(Re,De,Ve),U.setClearColor(ee,pe),yt!==void 0&&($.viewport=yt),U.toneMapping=st}function rn(w,G,Q){let $=G.isScene===!0?G.overrideMaterial:null;for(let Z=0,Ae=w.length;Z<Ae;Z++){let Le=w[Z],{object:Re,geometry:De,group:Ve}=Le,st=Le.material;st.allowOverride===!0&&$!==null&&(st=$),Re.layers.test(Q.layers)&&cn(Re,G,Q,De,st,Ve)}}function cn(w,G,Q,$,Z,Ae){B!==null&&Z.isNodeMaterial&&B.setObject(w,Z),w.onBeforeRender(U,G,Q,$,Z,Ae),w.modelViewMatrix.multiplyMatrices(Q.matrixWorldInverse,w.matrixWorld),w.normalMatrix.getNormalMatrix(w.modelViewMatrix),Z.onBeforeRender(U,G,Q,$,w,Ae),Z.transparent===!0&&Z.side===es&&Z.forceSinglePass===!1?(Z.side=$n,Z.needsUpdate=!0,U.renderBufferDirect(Q,G,$,Z,w,Ae),Z.side=rr,Z.needsUpdate=!0,U.renderBufferDirect(Q,G,$,Z,w,Ae),Z.side=es):U.renderBufferDirect(Q,G,$,Z,w,Ae),w.onAfterRender(U,G,Q,$,Z,Ae)}function hn(w){let G=0;for(let Q of w)Q.texture!==null&&G++;return G}function Gi(w,G,Q){G.isScene!==!0&&(G=ft);let $=Xe.get(w),Z=E.state.lights,Ae=E.state.shadowsArray,Le=Z.state.version,Re=oe.getParameters(w,Z.state,Ae,G,Q,E.state.lightProbeGridArray),De=oe.getProgramCacheKey(Re),Ve=$.programs;$.environment=w.isMeshStandardMaterial||w.isMeshLambertMaterial||w.isMeshPhongMaterial?G.environment:null,$.fog=G.fog;let st=w.isMeshStandardMaterial||w.isMeshLambertMaterial&&!w.envMap||w.isMeshPhongMaterial&&!w.envMap;$.envMap=R.get(w.envMap||$.environment,st),$.envMapRotation=$.environment!==null&&w.envMap===null?G.environmentRotation:w.envMapRotation,Ve===void 0&&(w.addEventListener("dispose",dt),Ve=new Map,$.programs=Ve,$.programVariants=new Map);let yt=Ve.get(De);if(yt!==void 0){if($.currentProgram===yt&&$.lightsStateVersion===Le)return Go(w,Re),yt}else Re.uniforms=oe.getUniforms(w),B!==null&&w.isNodeMaterial&&B.build(w,Q,Re),w.onBeforeCompile(Re,U),yt=oe.acquireProgram(Re,De),Ve.set(De,yt),$.uniforms=Re.uniforms;let He=$.uniforms;return(!w.isShaderMaterial&&!w.isRawShaderMaterial||w.clipping===!0)&&(He.clippingPlanes=se.uniform),Go(w,Re),$.needsLights=Rs(w),$.lightsStateVersion=Le,$.needsLights&&(He.ambientLightColor.value=Z.state.ambient,He.lightProbe.value=Z.state.probe,He.sunLights.value=Z.state.sun,He.sunLightShadows.value=Z.state.sunShadow,He.directionalLights.value=Z.state.directional,He.directionalLightShadows.value=Z.state.directionalShadow,He.spotLights.value=Z.state.spot,He.spotLightShadows.value=Z.state.spotShadow,He.rectAreaLights.value=Z.state.rectArea,He.ltc_1.value=Z.state.rectAreaLTC1,He.ltc_2.value=Z.state.rectAreaLTC2,He.pointLights.value=Z.state.point,He.pointLightShadows.value=Z.state.pointShadow,He.hemisphereLights.value=Z.state.hemi,He.sunShadowMatrix.value=Z.state.sunShadowMatrix,He.sunShadowCascade.value=Z.state.sunShadowCascade,He.directionalShadowMatrix.value=Z.state.directionalShadowMatrix,He.spotLightMatrix.value=Z.state.spotLightMatrix,He.spotLightMap.value=Z.state.spotLightMap,He.pointShadowMatrix.value=Z.state.pointShadowMatrix),$.numLightProbeGrids=hn(E.state.lightProbeGridArray),$.currentProgram=yt,$.uniformsList=null,yt}function ei(w,G,Q,$,Z){let Ae=Xe.get(w),Le=Ae.currentProgram.id+","+$+","+Z,Re=Ae.programVariants.get(Le);return Re===void 0?(Re=Gi(w,G,Q),Ae.programVariants.set(Le,Re)):(Ae.currentProgram=Re,Ae.uniformsList=null,Ae.outputColorSpace=$,Ae.toneMapping=Z),Re}function As(w){if(w.uniformsList===null){let G=w.currentProgram.getUniforms();w.uniformsList=Fo.seqWithValue(G.seq,w.uniforms)}return w.uniformsList}function Go(w,G){let Q=Xe.get(w);Q.outputColorSpace=G.outputColorSpace,Q.batching=G.batching,Q.batchingColor=G.batchingColor,Q.instancing=G.instancing,Q.instancingColor=G.instancingColor,Q.instancingMorph=G.instancingMorph,Q.skinning=G.skinning,Q.morphTargets=G.morphTargets,Q.morphNormals=G.morphNormals,Q.morphColors=G.morphColors,Q.morphTargetsCount=G.morphTargetsCount,Q.numClippingPlanes=G.numClippingPlanes,Q.numIntersection=G.numClipIntersection,Q.vertexAlphas=G.vertexAlphas,Q.vertexTangents=G.vertexTangents,Q.toneMapping=G.toneMapping}function Ho(w,G,Q,$,Z){G.isScene!==!0&&(G=ft),Ke.resetTextureUnits();let Ae=G.fog,Le=$.isMeshStandardMaterial||$.isMeshLambertMaterial||$.isMeshPhongMaterial?G.environment:null,Re=te===null?U.outputColorSpace:te.isXRRenderTarget===!0?te.texture.colorSpace:At.workingColorSpace,De=$.isMeshStandardMaterial||$.isMeshLambertMaterial&&!$.envMap||$.isMeshPhongMaterial&&!$.envMap,Ve=R.get($.envMap||Le,De),st=$.vertexColors===!0&&!!Q.attributes.color&&Q.attributes.color.itemSize===4,yt=!!Q.attributes.tangent&&(!!$.normalMap||$.anisotropy>0),He=!!Q.morphAttributes.position,vt=!!Q.morphAttributes.normal,tn=!!Q.morphAttributes.color,kt=ts;$.toneMapped&&(te===null||te.isXRRenderTarget===!0)&&(kt=U.toneMapping);let zt=Q.morphAttributes.position||Q.morphAttributes.normal||Q.morphAttributes.color,yn=zt!==void 0?zt.length:0,ke=Xe.get($),fn=E.state.lights;if(Rt===!0&&(Bt===!0||w!==q)){let Gt=w===q&&$.id===X;se.setState($,w,Gt)}let Et=!1,os=!1;$.version===ke.__version?ke.needsLights&&ke.lightsStateVersion!==fn.state.version||Z.isBatchedMesh&&ke.batching===!1||!Z.isBatchedMesh&&ke.batching===!0||Z.isBatchedMesh&&ke.batchingColor===!0&&Z._colorsTexture===null||Z.isBatchedMesh&&ke.batchingColor===!1&&Z._colorsTexture!==null||Z.isInstancedMesh&&ke.instancing===!1||!Z.isInstancedMesh&&ke.instancing===!0||Z.isSkinnedMesh&&ke.skinning===!1||!Z.isSkinnedMesh&&ke.skinning===!0||Z.isInstancedMesh&&ke.instancingColor===!0&&Z.instanceColor===null||Z.isInstancedMesh&&ke.instancingColor===!1&&Z.instanceColor!==null||Z.isInstancedMesh&&ke.instancingMorph===!0&&Z.morphTexture===null||Z.isInstancedMesh&&ke.instancingMorph===!1&&Z.morphTexture!==null||ke.envMap!==Ve||$.fog===!0&&ke.fog!==Ae||ke.numClippingPlanes!==void 0&&(ke.numClippingPlanes!==se.numPlanes||ke.numIntersection!==se.numIntersection)||ke.vertexAlphas!==st||ke.vertexTangents!==yt||ke.morphTargets!==He||ke.morphNormals!==vt||ke.morphColors!==tn||ke.morphTargetsCount!==yn||ke.numLightProbeGrids!==hn(E.state.lightProbeGridArray)?Et=!0:(ke.outputColorSpace!==Re||ke.toneMapping!==kt)&&(os=!0):(Et=!0,ke.__version=$.version);let dn=ke.currentProgram;(Et===!0||os===!0)&&(dn=os===!0?ei($,G,Z,Re,kt):Gi($,G,Z),B&&$.isNodeMaterial&&B.onUpdateProgram($,dn,ke));let Fr=!1,Hi=!1,as=!1,mt=dn.getUniforms(),on=ke.uniforms;if(Ee.useProgram(dn.program)&&(Fr=!0,Hi=!0,as=!0),$.id!==X&&(X=$.id,Hi=!0),Fr||q!==w){Ee.buffers.depth.getReversed()&&w.reversedDepth!==!0&&(w._reversedDepth=!0,w.updateProjectionMatrix()),mt.setValue(O,"projectionMatrix",w.projectionMatrix),mt.setValue(O,"viewMatrix",w.matrixWorldInverse);let pn=mt.map.cameraPosition;pn!==void 0&&pn.setValue(O,Ct.setFromMatrixPosition(w.matrixWorld)),ht.logarithmicDepthBuffer&&mt.setValue(O,"logDepthBufFC",2/(Math.log(w.far+1)/Math.LN2)),($.isMeshPhongMaterial||$.isMeshToonMaterial||$.isMeshLambertMaterial||$.isMeshBasicMaterial||$.isMeshStandardMaterial||$.isShaderMaterial)&&mt.setValue(O,"isOrthographic",w.isOrthographicCamera===!0),q!==w&&(q=w,Hi=!0,as=!0)}if(ke.needsLights&&(fn.state.sunShadowMap.length>0&&mt.setValue(O,"sunShadowMap",fn.state.sunShadowMap,Ke),fn.state.directionalShadowMap.length>0&&mt.setValue(O,"directionalShadowMap",fn.state.directionalShadowMap,Ke),fn.state.spotShadowMap.length>0&&mt.setValue(O,"spotShadowMap",fn.state.spotShadowMap,Ke),fn.state.pointShadowMap.length>0&&mt.setValue(O,"pointShadowMap",fn.state.pointShadowMap,Ke)),Z.isSkinnedMesh){mt.setOptional(O,Z,"bindMatrix"),mt.setOptional(O,Z,"bindMatrixInverse");let Gt=Z.skeleton;Gt&&(Gt.boneTexture===null&&Gt.computeBoneTexture(),mt.setValue(O,"boneTexture",Gt.boneTexture,Ke))}Z.isBatchedMesh&&(mt.setOptional(O,Z,"batchingTexture"),mt.setValue(O,"batchingTexture",Z._matricesTexture,Ke),mt.setOptional(O,Z,"batchingIdTexture"),mt.setValue(O,"batchingIdTexture",Z._indirectTexture,Ke),mt.setOptional(O,Z,"batchingColorTexture"),Z._colorsTexture!==null&&mt.setValue(O,"batchingColorTexture",Z._colorsTexture,Ke));let Gn=Q.morphAttributes;if((Gn.position!==void 0||Gn.normal!==void 0||Gn.color!==void 0)&&re.update(Z,Q,dn),(Hi||ke.receiveShadow!==Z.receiveShadow)&&(ke.receiveShadow=Z.receiveShadow,mt.setValue(O,"receiveShadow",Z.receiveShadow)),($.isMeshStandardMaterial||$.isMeshLambertMaterial||$.isMeshPhongMaterial)&&$.envMap===null&&G.environment!==null&&(on.envMapIntensity.value=G.environmentIntensity),on.dfgLUT!==void 0&&(on.dfgLUT.value=FE()),Hi){if(mt.setValue(O,"toneMappingExposure",U.toneMappingExposure),ke.needsLights&&Ur(on,as),Ae&&$.fog===!0&&ve.refreshFogUniforms(on,Ae),ve.refreshMaterialUniforms(on,$,ye,Me,E.state.transmissionRenderTarget[w.id]),ke.needsLights&&ke.numLightProbeGrids>0){let Gt=b,pn=0;for(let Un of E.state.lightProbeGridArray)Un.texture!==null&&(Gt.textures[pn]=Un.texture,Gt.min[pn]=Un.boundingBox.min,Gt.max[pn]=Un.boundingBox.max,Gt.resolution[pn]=Un.resolution,pn++);for(let Un in Gt)Gt[Un].length=pn;on.probesSH.value=Gt.textures,on.probesMin.value=Gt.min,on.probesMax.value=Gt.max,on.probesResolution.value=Gt.resolution}Fo.upload(O,As(ke),on,Ke)}if($.isShaderMaterial&&$.uniformsNeedUpdate===!0&&(Fo.upload(O,As(ke),on,Ke),$.uniformsNeedUpdate=!1),$.isSpriteMaterial&&mt.setValue(O,"center",Z.center),mt.setValue(O,"modelViewMatrix",Z.modelViewMatrix),mt.setValue(O,"normalMatrix",Z.normalMatrix),mt.setValue(O,"modelMatrix",Z.matrixWorld),$.uniformsGroups!==void 0){let Gt=$.uniformsGroups;for(let pn=0,Un=Gt.length;pn<Un;pn++){let tl=Gt[pn];Ye.update(tl,dn),Ye.bind(tl,dn)}}return dn}function Ur(w,G){w.ambientLightColor.needsUpdate=G,w.lightProbe.needsUpdate=G,w.sunLights.needsUpdate=G,w.sunLightShadows.needsUpdate=G,w.directionalLights.needsUpdate=G,w.directionalLightShadows.needsUpdate=G,w.pointLights.needsUpdate=G,w.pointLightShadows.needsUpdate=G,w.spotLights.needsUpdate=G,w.spotLightShadows.needsUpdate=G,w.rectAreaLights.needsUpdate=G,w.hemisphereLights.needsUpdate=G}function Rs(w){return w.isMeshLambertMaterial||w.isMeshToonMaterial||w.isMeshPhongMaterial||w.isMeshStandardMaterial||w.isShadowMaterial||w.isShaderMaterial&&w.lights===!0}this.getActiveCubeFace=function(){return W},this.getActiveMipmapLevel=function(){return D},this.getRenderTarget=function(){return te},this.setRenderTargetTextures=function(w,G,Q){let $=Xe.get(w);$.__autoAllocateDepthBuffer=w.resolveDepthBuffer===!1,$.__autoAllocateDepthBuffer===!1&&($.__useRenderToTexture=!1),Xe.get(w.texture).__webglTexture=G,Xe.get(w.depthTexture).__webglTexture=$.__autoAllocateDepthBuffer?void 0:Q,$.__hasExternalTextures=!0},this.setRenderTargetFramebuffer=function(w,G){let Q=Xe.get(w);Q.__webglFramebuffer=G,Q.__useDefaultFramebuffer=G===void 0},this.setRenderTarget=function(w,G=0,Q=0){te=w,W=G,D=Q;let $=null,Z=!1,Ae=!1;if(w){let Re=Xe.get(w);if(Re.__useDefaultFramebuffer!==void 0){Ee.bindFramebuffer(O.FRAMEBUFFER,Re.__webglFramebuffer),j.copy(w.viewport),ae.copy(w.scissor),ce=w.scissorTest,Ee.viewport(j),Ee.scissor(ae),Ee.setScissorTest(ce),X=-1;return}else if(Re.__webglFramebuffer===void 0)Ke.setupRenderTarget(w);else if(Re.__hasExternalTextures)Ke.rebindTextures(w,Xe.get(w.texture).__webglTexture,Xe.get(w.depthTexture).__webglTexture);else if(w.depthBuffer){let st=w.depthTexture;if(Re.__boundDepthTexture!==st){if(st!==null&&Xe.has(st)&&(w.width!==st.image.width||w.height!==st.image.height))throw new Error("THREE.WebGLRenderer: Attached DepthTexture is initialized to the incorrect size.");Ke.setupDepthRenderbuffer(w)}}let De=w.texture;(De.isData3DTexture||De.isDataArrayTexture||De.isCompressedArrayTexture)&&(Ae=!0);let Ve=Xe.get(w).__webglFramebuffer;w.isWebGLCubeRenderTarget?(Array.isArray(Ve[G])?$=Ve[G][Q]:$=Ve[G],Z=!0):w.samples>0&&Ke.useMultisampledRTT(w)===!1?$=Xe.get(w).__webglMultisampledFramebuffer:Array.isArray(Ve)?$=Ve[Q]:$=Ve,j.copy(w.viewport),ae.copy(w.scissor),ce=w.scissorTest}else j.copy(We).multiplyScalar(ye).floor(),ae.copy(Ce).multiplyScalar(ye).floor(),ce=Ne;if(Q!==0&&($=z),Ee.bindFramebuffer(O.FRAMEBUFFER,$)&&Ee.drawBuffers(w,$),Ee.viewport(j),Ee.scissor(ae),Ee.setScissorTest(ce),Z){let Re=Xe.get(w.texture);O.framebufferTexture2D(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_CUBE_MAP_POSITIVE_X+G,Re.__webglTexture,Q)}else if(Ae){let Re=G;for(let De=0;De<w.textures.length;De++){let Ve=Xe.get(w.textures[De]);O.framebufferTextureLayer(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0+De,Ve.__webglTexture,Q,Re)}}else if(w!==null&&Q!==0){let Re=Xe.get(w.texture);O.framebufferTexture2D(O.FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,Re.__webglTexture,Q)}X=-1};function Or(w){let G=Xe.get(w);return(G.__readFormat!==w.format||G.__readType!==w.type)&&(G.__readFormat=w.format,G.__readType=w.type,G.__formatReadable=ht.textureFormatReadable(w.format),G.__typeReadable=ht.textureTypeReadable(w.type)),G}this.readRenderTargetPixels=function(w,G,Q,$,Z,Ae,Le,Re=0){if(!(w&&w.isWebGLRenderTarget)){rt("WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");return}let De=Xe.get(w).__webglFramebuffer;if(w.isWebGLCubeRenderTarget&&Le!==void 0&&(De=De[Le],Array.isArray(De)&&(De=De[0])),De){Ee.bindFramebuffer(O.FRAMEBUFFER,De);try{let Ve=w.textures[Re],st=Ve.format,yt=Ve.type;w.textures.length>1&&O.readBuffer(O.COLOR_ATTACHMENT0+Re);let He=Or(Ve);if(He.__formatReadable===!1){rt("WebGLRenderer.readRenderTargetPixels: renderTarget is not in RGBA or implementation defined format.");return}if(He.__typeReadable===!1){rt("WebGLRenderer.readRenderTargetPixels: renderTarget is not in UnsignedByteType or implementation defined type.");return}G>=0&&G<=w.width-$&&Q>=0&&Q<=w.height-Z&&O.readPixels(G,Q,$,Z,xe.convert(st),xe.convert(yt),Ae)}finally{let Ve=te!==null?Xe.get(te).__webglFramebuffer:null;Ee.bindFramebuffer(O.FRAMEBUFFER,Ve)}}},this.readRenderTargetPixelsAsync=async function(w,G,Q,$,Z,Ae,Le,Re=0){if(!(w&&w.isWebGLRenderTarget))throw new Error("THREE.WebGLRenderer.readRenderTargetPixels: renderTarget is not THREE.WebGLRenderTarget.");let De=Xe.get(w).__webglFramebuffer;if(w.isWebGLCubeRenderTarget&&Le!==void 0&&(De=De[Le],Array.isArray(De)&&(De=De[0])),De)if(G>=0&&G<=w.width-$&&Q>=0&&Q<=w.height-Z){Ee.bindFramebuffer(O.FRAMEBUFFER,De);let Ve=w.textures[Re],st=Ve.format,yt=Ve.type;w.textures.length>1&&O.readBuffer(O.COLOR_ATTACHMENT0+Re);let He=Or(Ve);if(He.__formatReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in RGBA or implementation defined format.");if(He.__typeReadable===!1)throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: renderTarget is not in UnsignedByteType or implementation defined type.");let vt=O.createBuffer();O.bindBuffer(O.PIXEL_PACK_BUFFER,vt),O.bufferData(O.PIXEL_PACK_BUFFER,Ae.byteLength,O.STREAM_READ),O.readPixels(G,Q,$,Z,xe.convert(st),xe.convert(yt),0),O.bindBuffer(O.PIXEL_PACK_BUFFER,null);let tn=te!==null?Xe.get(te).__webglFramebuffer:null;Ee.bindFramebuffer(O.FRAMEBUFFER,tn);let kt=O.fenceSync(O.SYNC_GPU_COMMANDS_COMPLETE,0);return O.flush(),await M0(O,kt,4),O.bindBuffer(O.PIXEL_PACK_BUFFER,vt),O.getBufferSubData(O.PIXEL_PACK_BUFFER,0,Ae),O.bindBuffer(O.PIXEL_PACK_BUFFER,null),O.deleteBuffer(vt),O.deleteSync(kt),Ae}else throw new Error("THREE.WebGLRenderer.readRenderTargetPixelsAsync: requested read bounds are out of range.")},this.copyFramebufferToTexture=function(w,G=null,Q=0){let $=Math.pow(2,-Q),Z=Math.floor(w.image.width*$),Ae=Math.floor(w.image.height*$),Le=G!==null?G.x:0,Re=G!==null?G.y:0;Ke.setTexture2D(w,0),O.copyTexSubImage2D(O.TEXTURE_2D,Q,0,0,Le,Re,Z,Ae),Ee.unbindTexture()},this.copyTextureToTexture=function(w,G,Q=null,$=null,Z=0,Ae=0){let Le,Re,De,Ve,st,yt,He,vt,tn,kt=w.isCompressedTexture?w.mipmaps[Ae]:w.image;if(Q!==null)Le=Q.max.x-Q.min.x,Re=Q.max.y-Q.min.y,De=Q.isBox3?Q.max.z-Q.min.z:1,Ve=Q.min.x,st=Q.min.y,yt=Q.isBox3?Q.min.z:0;else{let mt=Math.pow(2,-Z);Le=Math.floor(kt.width*mt),Re=Math.floor(kt.height*mt),w.isDataArrayTexture?De=kt.depth:w.isData3DTexture?De=Math.floor(kt.depth*mt):De=1,Ve=0,st=0,yt=0}$!==null?(He=$.x,vt=$.y,tn=$.z):(He=0,vt=0,tn=0);let zt=xe.convert(G.format),yn=xe.convert(G.type),ke;G.isData3DTexture?(Ke.setTexture3D(G,0),ke=O.TEXTURE_3D):G.isDataArrayTexture||G.isCompressedArrayTexture?(Ke.setTexture2DArray(G,0),ke=O.TEXTURE_2D_ARRAY):(Ke.setTexture2D(G,0),ke=O.TEXTURE_2D),Ee.activeTexture(O.TEXTURE0),Ee.pixelStorei(O.UNPACK_FLIP_Y_WEBGL,G.flipY),Ee.pixelStorei(O.UNPACK_PREMULTIPLY_ALPHA_WEBGL,G.premultiplyAlpha),Ee.pixelStorei(O.UNPACK_ALIGNMENT,G.unpackAlignment);let fn=Ee.getParameter(O.UNPACK_ROW_LENGTH),Et=Ee.getParameter(O.UNPACK_IMAGE_HEIGHT),os=Ee.getParameter(O.UNPACK_SKIP_PIXELS),dn=Ee.getParameter(O.UNPACK_SKIP_ROWS),Fr=Ee.getParameter(O.UNPACK_SKIP_IMAGES);Ee.pixelStorei(O.UNPACK_ROW_LENGTH,kt.width),Ee.pixelStorei(O.UNPACK_IMAGE_HEIGHT,kt.height),Ee.pixelStorei(O.UNPACK_SKIP_PIXELS,Ve),Ee.pixelStorei(O.UNPACK_SKIP_ROWS,st),Ee.pixelStorei(O.UNPACK_SKIP_IMAGES,yt);let Hi=w.isDataArrayTexture||w.isData3DTexture,as=G.isDataArrayTexture||G.isData3DTexture;if(w.isDepthTexture){let mt=Xe.get(w),on=Xe.get(G),Gn=Xe.get(mt.__renderTarget),Gt=Xe.get(on.__renderTarget);Ee.bindFramebuffer(O.READ_FRAMEBUFFER,Gn.__webglFramebuffer),Ee.bindFramebuffer(O.DRAW_FRAMEBUFFER,Gt.__webglFramebuffer);for(let pn=0;pn<De;pn++)Hi&&(O.framebufferTextureLayer(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,Xe.get(w).__webglTexture,Z,yt+pn),O.framebufferTextureLayer(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,Xe.get(G).__webglTexture,Ae,tn+pn)),O.blitFramebuffer(Ve,st,Ve+Le,st+Re,He,vt,He+Le,vt+Re,O.DEPTH_BUFFER_BIT,O.NEAREST);Ee.bindFramebuffer(O.READ_FRAMEBUFFER,null),Ee.bindFramebuffer(O.DRAW_FRAMEBUFFER,null)}else if(Z!==0||w.isRenderTargetTexture||Xe.has(w)){let mt=Xe.get(w),on=Xe.get(G);Ee.bindFramebuffer(O.READ_FRAMEBUFFER,L),Ee.bindFramebuffer(O.DRAW_FRAMEBUFFER,H);for(let Gn=0;Gn<De;Gn++)Hi?O.framebufferTextureLayer(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,mt.__webglTexture,Z,yt+Gn):O.framebufferTexture2D(O.READ_FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,mt.__webglTexture,Z),as?O.framebufferTextureLayer(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,on.__webglTexture,Ae,tn+Gn):O.framebufferTexture2D(O.DRAW_FRAMEBUFFER,O.COLOR_ATTACHMENT0,O.TEXTURE_2D,on.__webglTexture,Ae),Z!==0?O.blitFramebuffer(Ve,st,Ve+Le,st+Re,He,vt,He+Le,vt+Re,O.COLOR_BUFFER_BIT,O.NEAREST):as?O.copyTexSubImage3D(ke,Ae,He,vt,tn+Gn,Ve,st,Le,Re):O.copyTexSubImage2D(ke,Ae,He,vt,Ve,st,Le,Re);Ee.bindFramebuffer(O.READ_FRAMEBUFFER,null),Ee.bindFramebuffer(O.DRAW_FRAMEBUFFER,null)}else as?w.isDataTexture||w.isData3DTexture?O.texSubImage3D(ke,Ae,He,vt,tn,Le,Re,De,zt,yn,kt.data):G.isCompressedArrayTexture?O.compressedTexSubImage3D(ke,Ae,He,vt,tn,Le,Re,De,zt,kt.data):O.texSubImage3D(ke,Ae,He,vt,tn,Le,Re,De,zt,yn,kt):w.isDataTexture?O.texSubImage2D(O.TEXTURE_2D,Ae,He,vt,Le,Re,zt,yn,kt.data):w.isCompressedTexture?O.compressedTexSubImage2D(O.TEXTURE_2D,Ae,He,vt,kt.width,kt.height,zt,kt.data):O.texSubImage2D(O.TEXTURE_2D,Ae,He,vt,Le,Re,zt,yn,kt);Ee.pixelStorei(O.UNPACK_ROW_LENGTH,fn),Ee.pixelStorei(O.UNPACK_IMAGE_HEIGHT,Et),Ee.pixelStorei(O.UNPACK_SKIP_PIXELS,os),Ee.pixelStorei(O.UNPACK_SKIP_ROWS,dn),Ee.pixelStorei(O.UNPACK_SKIP_IMAGES,Fr),Ae===0&&G.generateMipmaps===!0&&G.mipmapsAutoUpdate===!0&&O.generateMipmap(ke),Ee.unbindTexture()},this.initRenderTarget=function(w){Xe.get(w).__webglFramebuffer===void 0&&Ke.setupRenderTarget(w)},this.initTexture=function(w){w.isCubeTexture?Ke.setTextureCube(w,0):w.isData3DTexture?Ke.setTexture3D(w,0):w.isDataArrayTexture||w.isCompressedArrayTexture?Ke.setTexture2DArray(w,0):Ke.setTexture2D(w,0),Ee.unbindTexture()},this.resetState=function(){W=0,D=0,te=null,Ee.reset(),we.reset()},typeof __THREE_DEVTOOLS__<"u"&&__THREE_DEVTOOLS__.dispatchEvent(new CustomEvent("observe",{detail:this}))}get coordinateSystem(){return Mi}get outputColorSpace(){return this._outputColorSpace}set outputColorSpace(e){this._outputColorSpace=e;let t=this.getContext();t.drawingBufferColorSpace=At._getDrawingBufferColorSpace(e),t.unpackColorSpace=At._getUnpackColorSpace()}};var c_={type:"change"},Ad={type:"start"},u_={type:"end"},zh=new Qs,h_=new ui,kE=Math.cos(70*od.DEG2RAD),wn=new K,Qn=2*Math.PI,Dt={NONE:-1,ROTATE:0,DOLLY:1,PAN:2,TOUCH_ROTATE:3,TOUCH_PAN:4,TOUCH_DOLLY_PAN:5,TOUCH_DOLLY_ROTATE:6},Td=1e-6,Gh=class extends Ga{constructor(e,t=null){super(e,t),this.state=Dt.NONE,this.target=new K,this.cursor=new K,this.minDistance=0,this.maxDistance=1/0,this.minZoom=0,this.maxZoom=1/0,this.minTargetRadius=0,this.maxTargetRadius=1/0,this.minPolarAngle=0,this.maxPolarAngle=Math.PI,this.minAzimuthAngle=-1/0,this.maxAzimuthAngle=1/0,this.enableDamping=!1,this.dampingFactor=.05,this.enableZoom=!0,this.zoomSpeed=1,this.enableRotate=!0,this.rotateSpeed=1,this.keyRotateSpeed=1,this.enablePan=!0,this.panSpeed=1,this.screenSpacePanning=!0,this.keyPanSpeed=7,this.zoomToCursor=!1,this.autoRotate=!1,this.autoRotateSpeed=2,this.keys={LEFT:"ArrowLeft",UP:"ArrowUp",RIGHT:"ArrowRight",BOTTOM:"ArrowDown"},this.mouseButtons={LEFT:ir.ROTATE,MIDDLE:ir.DOLLY,RIGHT:ir.PAN},this.touches={ONE:sr.ROTATE,TWO:sr.DOLLY_PAN},this.target0=this.target.clone(),this.position0=this.object.position.clone(),this.zoom0=this.object.zoom,this._cursorStyle="auto",this._domElementKeyEvents=null,this._lastPosition=new K,this._lastQuaternion=new di,this._lastTargetPosition=new K,this._quat=new di().setFromUnitVectors(e.up,new K(0,1,0)),this._quatInverse=this._quat.clone().invert(),this._spherical=new Po,this._sphericalDelta=new Po,this._scale=1,this._panOffset=new K,this._rotateStart=new ut,this._rotateEnd=new ut,this._rotateDelta=new ut,this._panStart=new ut,this._panEnd=new ut,this._panDelta=new ut,this._dollyStart=new ut,this._dollyEnd=new ut,this._dollyDelta=new ut,this._dollyDirection=new K,this._mouse=new ut,this._performCursorZoom=!1,this._pointers=[],this._pointerPositions={},this._controlActive=!1,this._onPointerMove=GE.bind(this),this._onPointerDown=zE.bind(this),this._onPointerUp=HE.bind(this),this._onContextMenu=ZE.bind(this),this._onMouseWheel=XE.bind(this),this._onKeyDown=qE.bind(this),this._onTouchStart=YE.bind(this),this._onTouchMove=$E.bind(this),this._onMouseDown=VE.bind(this),this._onMouseMove=WE.bind(this),this._interceptControlDown=KE.bind(this),this._interceptControlUp=JE.bind(this),this.domElement!==null&&this.connect(this.domElement),this.update()}set cursorStyle(e){this._cursorStyle=e,e==="grab"?this.domElement.style.cursor="grab":this.domElement.style.cursor="auto"}get cursorStyle(){return this._cursorStyle}connect(e){super.connect(e),this.domElement.addEventListener("pointerdown",this._onPointerDown),this.domElement.addEventListener("pointercancel",this._onPointerUp),this.domElement.addEventListener("contextmenu",this._onContextMenu),this.domElement.addEventListener("wheel",this._onMouseWheel,{passive:!1}),this.domElement.ownerDocument.addEventListener("keydown",this._interceptControlDown,{passive:!0,capture:!0}),this.domElement.style.touchAction="none"}disconnect(){this.state=Dt.NONE,this.domElement.removeEventListener("pointerdown",this._onPointerDown),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.domElement.removeEventListener("pointercancel",this._onPointerUp),this.domElement.removeEventListener("wheel",this._onMouseWheel),this.domElement.removeEventListener("contextmenu",this._onContextMenu),this.stopListenToKeyEvents(),this.domElement.ownerDocument.removeEventListener("keydown",this._interceptControlDown,{capture:!0}),this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{capture:!0}),this._controlActive=!1,this._pointers.length=0,this._pointerPositions={},this.domElement.style.touchAction="",this.domElement.style.cursor="auto"}dispose(){this.disconnect()}getPolarAngle(){return this._spherical.phi}getAzimuthalAngle(){return this._spherical.theta}getDistance(){return this.object.position.distanceTo(this.target)}listenToKeyEvents(e){e.addEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=e}stopListenToKeyEvents(){this._domElementKeyEvents!==null&&(this._domElementKeyEvents.removeEventListener("keydown",this._onKeyDown),this._domElementKeyEvents=null)}saveState(){this.target0.copy(this.target),this.position0.copy(this.object.position),this.zoom0=this.object.zoom}reset(){this.target.copy(this.target0),this.object.position.copy(this.position0),this.object.zoom=this.zoom0,this.object.updateProjectionMatrix(),this.dispatchEvent(c_),this.update(),this.state=Dt.NONE}pan(e,t){this._pan(e,t),this.update()}dollyIn(e){this._dollyIn(e),this.update()}dollyOut(e){this._dollyOut(e),this.update()}rotateLeft(e){this._rotateLeft(e),this.update()}rotateUp(e){this._rotateUp(e),this.update()}update(e=null){let t=this.object.position;wn.copy(t).sub(this.target),wn.applyQuaternion(this._quat),this._spherical.setFromVector3(wn),this.autoRotate&&this.state===Dt.NONE&&this._rotateLeft(this._getAutoRotationAngle(e)),this.enableDamping?(this._spherical.theta+=this._sphericalDelta.theta*this.dampingFactor,this._spherical.phi+=this._sphericalDelta.phi*this.dampingFactor):(this._spherical.theta+=this._sphericalDelta.theta,this._spherical.phi+=this._sphericalDelta.phi);let i=this.minAzimuthAngle,s=this.maxAzimuthAngle;isFinite(i)&&isFinite(s)&&(i<-Math.PI?i+=Qn:i>Math.PI&&(i-=Qn),s<-Math.PI?s+=Qn:s>Math.PI&&(s-=Qn),i<=s?this._spherical.theta=Math.max(i,Math.min(s,this._spherical.theta)):this._spherical.theta=this._spherical.theta>(i+s)/2?Math.max(i,this._spherical.theta):Math.min(s,this._spherical.theta)),this._spherical.phi=Math.max(this.minPolarAngle,Math.min(this.maxPolarAngle,this._spherical.phi)),this._spherical.makeSafe(),this.enableDamping===!0?this.target.addScaledVector(this._panOffset,this.dampingFactor):this.target.add(this._panOffset),this.target.sub(this.cursor),this.target.clampLength(this.minTargetRadius,this.maxTargetRadius),this.target.add(this.cursor);let r=!1;if(this.zoomToCursor&&this._performCursorZoom||this.object.isOrthographicCamera)this._spherical.radius=this._clampDistance(this._spherical.radius);else{let o=this._spherical.radius;this._spherical.radius=this._clampDistance(this._spherical.radius*this._scale),r=o!=this._spherical.radius}if(wn.setFromSpherical(this._spherical),wn.applyQuaternion(this._quatInverse),t.copy(this.target).add(wn),this.object.lookAt(this.target),this.enableDamping===!0?(this._sphericalDelta.theta*=1-this.dampingFactor,this._sphericalDelta.phi*=1-this.dampingFactor,this._panOffset.multiplyScalar(1-this.dampingFactor)):(this._sphericalDelta.set(0,0,0),this._panOffset.set(0,0,0)),this.zoomToCursor&&this._performCursorZoom){let o=null;if(this.object.isPerspectiveCamera){let a=wn.length();o=this._clampDistance(a*this._scale);let l=a-o;this.object.position.addScaledVector(this._dollyDirection,l),this.object.updateMatrixWorld(),r=!!l}else if(this.object.isOrthographicCamera){let a=new K(this._mouse.x,this._mouse.y,0);a.unproject(this.object);let l=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),this.object.updateProjectionMatrix(),r=l!==this.object.zoom;let c=new K(this._mouse.x,this._mouse.y,0);c.unproject(this.object),this.object.position.sub(c).add(a),this.object.updateMatrixWorld(),o=wn.length()}else console.warn("WARNING: OrbitControls.js encountered an unknown camera type - zoom to cursor disabled."),this.zoomToCursor=!1;o!==null&&(this.screenSpacePanning?this.target.set(0,0,-1).transformDirection(this.object.matrix).multiplyScalar(o).add(this.object.position):(zh.origin.copy(this.object.position),zh.direction.set(0,0,-1).transformDirection(this.object.matrix),Math.abs(this.object.up.dot(zh.direction))<kE?this.object.lookAt(this.target):(h_.setFromNormalAndCoplanarPoint(this.object.up,this.target),zh.intersectPlane(h_,this.target))))}else if(this.object.isOrthographicCamera){let o=this.object.zoom;this.object.zoom=Math.max(this.minZoom,Math.min(this.maxZoom,this.object.zoom/this._scale)),o!==this.object.zoom&&(this.object.updateProjectionMatrix(),r=!0)}return this._scale=1,this._performCursorZoom=!1,r||this._lastPosition.distanceToSquared(this.object.position)>Td||8*(1-this._lastQuaternion.dot(this.object.quaternion))>Td||this._lastTargetPosition.distanceToSquared(this.target)>Td?(this.dispatchEvent(c_),this._lastPosition.copy(this.object.position),this._lastQuaternion.copy(this.object.quaternion),this._lastTargetPosition.copy(this.target),!0):!1}_getAutoRotationAngle(e){return e!==null?Qn/60*this.autoRotateSpeed*e:Qn/60/60*this.autoRotateSpeed}_getZoomScale(e){let t=Math.abs(e*.01);return Math.pow(.95,this.zoomSpeed*t)}_rotateLeft(e){this._sphericalDelta.theta-=e}_rotateUp(e){this._sphericalDelta.phi-=e}_panLeft(e,t){wn.setFromMatrixColumn(t,0),wn.multiplyScalar(-e),this._panOffset.add(wn)}_panUp(e,t){this.screenSpacePanning===!0?wn.setFromMatrixColumn(t,1):(wn.setFromMatrixColumn(t,0),wn.crossVectors(this.object.up,wn)),wn.multiplyScalar(e),this._panOffset.add(wn)}_pan(e,t){let i=this.domElement;if(this.object.isPerspectiveCamera){let s=this.object.position;wn.copy(s).sub(this.target);let r=wn.length();r*=Math.tan(this.object.fov/2*Math.PI/180),this._panLeft(2*e*r/i.clientHeight,this.object.matrix),this._panUp(2*t*r/i.clientHeight,this.object.matrix)}else this.object.isOrthographicCamera?(this._panLeft(e*(this.object.right-this.object.left)/this.object.zoom/i.clientWidth,this.object.matrix),this._panUp(t*(this.object.top-this.object.bottom)/this.object.zoom/i.clientHeight,this.object.matrix)):(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - pan disabled."),this.enablePan=!1)}_dollyOut(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale/=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_dollyIn(e){this.object.isPerspectiveCamera||this.object.isOrthographicCamera?this._scale*=e:(console.warn("WARNING: OrbitControls.js encountered an unknown camera type - dolly/zoom disabled."),this.enableZoom=!1)}_updateZoomParameters(e,t){if(!this.zoomToCursor)return;this._performCursorZoom=!0;let i=this.domElement.getBoundingClientRect(),s=e-i.left,r=t-i.top,o=i.width,a=i.height;this._mouse.x=s/o*2-1,this._mouse.y=-(r/a)*2+1,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()}_clampDistance(e){return Math.max(this.minDistance,Math.min(this.maxDistance,e))}_handleMouseDownRotate(e){this._rotateStart.set(e.clientX,e.clientY)}_handleMouseDownDolly(e){this._updateZoomParameters(e.clientX,e.clientY),this._dollyStart.set(e.clientX,e.clientY)}_handleMouseDownPan(e){this._panStart.set(e.clientX,e.clientY)}_handleMouseMoveRotate(e){this._rotateEnd.set(e.clientX,e.clientY),this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(Qn*this._rotateDelta.x/t.clientHeight),this._rotateUp(Qn*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd),this.update()}_handleMouseMoveDolly(e){this._dollyEnd.set(e.clientX,e.clientY),this._dollyDelta.subVectors(this._dollyEnd,this._dollyStart),this._dollyDelta.y>0?this._dollyOut(this._getZoomScale(this._dollyDelta.y)):this._dollyDelta.y<0&&this._dollyIn(this._getZoomScale(this._dollyDelta.y)),this._dollyStart.copy(this._dollyEnd),this.zoomToCursor&&(this._performCursorZoom=!0,this._dollyDirection.set(this._mouse.x,this._mouse.y,1).unproject(this.object).sub(this.object.position).normalize()),this.update()}_handleMouseMovePan(e){this._panEnd.set(e.clientX,e.clientY),this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd),this.update()}_handleMouseWheel(e){this._updateZoomParameters(e.clientX,e.clientY),e.deltaY<0?this._dollyIn(this._getZoomScale(e.deltaY)):e.deltaY>0&&this._dollyOut(this._getZoomScale(e.deltaY)),this.update()}_handleKeyDown(e){let t=!1;switch(e.code){case this.keys.UP:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(Qn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,this.keyPanSpeed),t=!0;break;case this.keys.BOTTOM:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateUp(-Qn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(0,-this.keyPanSpeed),t=!0;break;case this.keys.LEFT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(Qn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(this.keyPanSpeed,0),t=!0;break;case this.keys.RIGHT:e.ctrlKey||e.metaKey||e.shiftKey?this.enableRotate&&this._rotateLeft(-Qn*this.keyRotateSpeed/this.domElement.clientHeight):this.enablePan&&this._pan(-this.keyPanSpeed,0),t=!0;break}t&&(e.preventDefault(),this.update())}_handleTouchStartRotate(e){if(this._pointers.length===1)this._rotateStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._rotateStart.set(i,s)}}_handleTouchStartPan(e){if(this._pointers.length===1)this._panStart.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panStart.set(i,s)}}_handleTouchStartDolly(e){let t=this._getSecondPointerPosition(e),i=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(i*i+s*s);this._dollyStart.set(0,r)}_handleTouchStartDollyPan(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enablePan&&this._handleTouchStartPan(e)}_handleTouchStartDollyRotate(e){this.enableZoom&&this._handleTouchStartDolly(e),this.enableRotate&&this._handleTouchStartRotate(e)}_handleTouchMoveRotate(e){if(this._pointers.length==1)this._rotateEnd.set(e.pageX,e.pageY);else{let i=this._getSecondPointerPosition(e),s=.5*(e.pageX+i.x),r=.5*(e.pageY+i.y);this._rotateEnd.set(s,r)}this._rotateDelta.subVectors(this._rotateEnd,this._rotateStart).multiplyScalar(this.rotateSpeed);let t=this.domElement;this._rotateLeft(Qn*this._rotateDelta.x/t.clientHeight),this._rotateUp(Qn*this._rotateDelta.y/t.clientHeight),this._rotateStart.copy(this._rotateEnd)}_handleTouchMovePan(e){if(this._pointers.length===1)this._panEnd.set(e.pageX,e.pageY);else{let t=this._getSecondPointerPosition(e),i=.5*(e.pageX+t.x),s=.5*(e.pageY+t.y);this._panEnd.set(i,s)}this._panDelta.subVectors(this._panEnd,this._panStart).multiplyScalar(this.panSpeed),this._pan(this._panDelta.x,this._panDelta.y),this._panStart.copy(this._panEnd)}_handleTouchMoveDolly(e){let t=this._getSecondPointerPosition(e),i=e.pageX-t.x,s=e.pageY-t.y,r=Math.sqrt(i*i+s*s);this._dollyEnd.set(0,r),this._dollyDelta.set(0,Math.pow(this._dollyEnd.y/this._dollyStart.y,this.zoomSpeed)),this._dollyOut(this._dollyDelta.y),this._dollyStart.copy(this._dollyEnd);let o=(e.pageX+t.x)*.5,a=(e.pageY+t.y)*.5;this._updateZoomParameters(o,a)}_handleTouchMoveDollyPan(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enablePan&&this._handleTouchMovePan(e)}_handleTouchMoveDollyRotate(e){this.enableZoom&&this._handleTouchMoveDolly(e),this.enableRotate&&this._handleTouchMoveRotate(e)}_addPointer(e){this._pointers.push(e.pointerId)}_removePointer(e){delete this._pointerPositions[e.pointerId];for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId){this._pointers.splice(t,1);return}}_isTrackingPointer(e){for(let t=0;t<this._pointers.length;t++)if(this._pointers[t]==e.pointerId)return!0;return!1}_trackPointer(e){let t=this._pointerPositions[e.pointerId];t===void 0&&(t=new ut,this._pointerPositions[e.pointerId]=t),t.set(e.pageX,e.pageY)}_getSecondPointerPosition(e){let t=e.pointerId===this._pointers[0]?this._pointers[1]:this._pointers[0];return this._pointerPositions[t]}_customWheelEvent(e){let t=e.deltaMode,i={clientX:e.clientX,clientY:e.clientY,deltaY:e.deltaY};switch(t){case 1:i.deltaY*=16;break;case 2:i.deltaY*=100;break}return e.ctrlKey&&!this._controlActive&&(i.deltaY*=10),i}};function zE(n){this.enabled!==!1&&(this._pointers.length===0&&(this.domElement.setPointerCapture(n.pointerId),this.domElement.ownerDocument.addEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.addEventListener("pointerup",this._onPointerUp)),!this._isTrackingPointer(n)&&(this._addPointer(n),n.pointerType==="touch"?this._onTouchStart(n):this._onMouseDown(n),this._cursorStyle==="grab"&&(this.domElement.style.cursor="grabbing")))}function GE(n){this.enabled!==!1&&(n.pointerType==="touch"?this._onTouchMove(n):this._onMouseMove(n))}function HE(n){switch(this._removePointer(n),this._pointers.length){case 0:this.domElement.releasePointerCapture(n.pointerId),this.domElement.ownerDocument.removeEventListener("pointermove",this._onPointerMove),this.domElement.ownerDocument.removeEventListener("pointerup",this._onPointerUp),this.dispatchEvent(u_),this.state=Dt.NONE,this._cursorStyle==="grab"&&(this.domElement.style.cursor="grab");break;case 1:let e=this._pointers[0],t=this._pointerPositions[e];this._onTouchStart({pointerId:e,pageX:t.x,pageY:t.y});break}}function VE(n){let e;switch(n.button){case 0:e=this.mouseButtons.LEFT;break;case 1:e=this.mouseButtons.MIDDLE;break;case 2:e=this.mouseButtons.RIGHT;break;default:e=-1}switch(e){case ir.DOLLY:if(this.enableZoom===!1)return;this._handleMouseDownDolly(n),this.state=Dt.DOLLY;break;case ir.ROTATE:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=Dt.PAN}else{if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=Dt.ROTATE}break;case ir.PAN:if(n.ctrlKey||n.metaKey||n.shiftKey){if(this.enableRotate===!1)return;this._handleMouseDownRotate(n),this.state=Dt.ROTATE}else{if(this.enablePan===!1)return;this._handleMouseDownPan(n),this.state=Dt.PAN}break;default:this.state=Dt.NONE}this.state!==Dt.NONE&&this.dispatchEvent(Ad)}function WE(n){switch(this.state){case Dt.ROTATE:if(this.enableRotate===!1)return;this._handleMouseMoveRotate(n);break;case Dt.DOLLY:if(this.enableZoom===!1)return;this._handleMouseMoveDolly(n);break;case Dt.PAN:if(this.enablePan===!1)return;this._handleMouseMovePan(n);break}}function XE(n){this.enabled===!1||this.enableZoom===!1||this.state!==Dt.NONE||(n.preventDefault(),this.dispatchEvent(Ad),this._handleMouseWheel(this._customWheelEvent(n)),this.dispatchEvent(u_))}function qE(n){this.enabled!==!1&&this._handleKeyDown(n)}function YE(n){switch(this._trackPointer(n),this._pointers.length){case 1:switch(this.touches.ONE){case sr.ROTATE:if(this.enableRotate===!1){this.state=Dt.NONE;break}this._handleTouchStartRotate(n),this.state=Dt.TOUCH_ROTATE;break;case sr.PAN:if(this.enablePan===!1){this.state=Dt.NONE;break}this._handleTouchStartPan(n),this.state=Dt.TOUCH_PAN;break;default:this.state=Dt.NONE}break;case 2:switch(this.touches.TWO){case sr.DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchStartDollyPan(n),this.state=Dt.TOUCH_DOLLY_PAN;break;case sr.DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchStartDollyRotate(n),this.state=Dt.TOUCH_DOLLY_ROTATE;break;default:this.state=Dt.NONE}break;default:this.state=Dt.NONE}this.state!==Dt.NONE&&this.dispatchEvent(Ad)}function $E(n){switch(this._trackPointer(n),this.state){case Dt.TOUCH_ROTATE:if(this.enableRotate===!1)return;this._handleTouchMoveRotate(n),this.update();break;case Dt.TOUCH_PAN:if(this.enablePan===!1)return;this._handleTouchMovePan(n),this.update();break;case Dt.TOUCH_DOLLY_PAN:if(this.enableZoom===!1&&this.enablePan===!1)return;this._handleTouchMoveDollyPan(n),this.update();break;case Dt.TOUCH_DOLLY_ROTATE:if(this.enableZoom===!1&&this.enableRotate===!1)return;this._handleTouchMoveDollyRotate(n),this.update();break;default:this.state=Dt.NONE}}function ZE(n){this.enabled!==!1&&n.preventDefault()}function KE(n){n.key==="Control"&&(this._controlActive=!0,this.domElement.ownerDocument.addEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}function JE(n){n.key==="Control"&&(this._controlActive=!1,this.domElement.ownerDocument.removeEventListener("keyup",this._interceptControlUp,{passive:!0,capture:!0}))}var Hh=256,Rd=(()=>{let n=new Float32Array(Hh*3),e=new gt;for(let t=0;t<Hh;t++)e.setHSL(.66*(1-t/(Hh-1)),.9,.55),n.set([e.r,e.g,e.b],t*3);return n})(),Vh=class{constructor(e){this.parent=e;this.renderer=new Fh({antialias:!1,preserveDrawingBuffer:!0}),this.renderer.setPixelRatio(Math.min(window.devicePixelRatio||1,2)),this.renderer.setClearColor(725014),e.appendChild(this.renderer.domElement),this.camera=new qn(60,1,.05,200),this.camera.up.set(0,0,1),this.camera.position.set(-8,-8,7),this.controls=new Gh(this.camera,this.renderer.domElement),this.controls.addEventListener("change",()=>this.dirty=!0),this.points=new La(this.geometry,new Ro({size:.06,vertexColors:!0})),this.points.frustumCulled=!1,this.scene.add(this.points);let t=new ka(20,20,3885658,1844785);t.rotation.x=Math.PI/2,this.scene.add(t,new za(1)),this.ro=new ResizeObserver(()=>this.resize()),this.ro.observe(e);let i=()=>{this.dirty&&this.render(),this.raf=requestAnimationFrame(i)};this.raf=requestAnimationFrame(i)}parent;renderer;scene=new Ra;camera;controls;geometry=new jn;points;capacity=0;cloud;dirty=!0;raf=0;ro;colourBy="height";onShown=null;pending=!1;pendingStamp=null;lastCount=0;resize(){let e=this.parent.clientWidth,t=Math.max(200,this.parent.clientHeight-4);this.renderer.setSize(e,t,!0),this.camera.aspect=e/t,this.camera.updateProjectionMatrix(),this.dirty=!0}show(e){let t=performance.now();this.cloud=Op(e,this.cloud);let i=this.cloud.count;i>this.capacity&&(this.capacity=Math.max(i,Math.ceil(this.capacity*1.5)),this.geometry.setAttribute("position",new fi(new Float32Array(this.capacity*3),3)),this.geometry.setAttribute("color",new fi(new Float32Array(this.capacity*3),3)));let s=this.geometry.getAttribute("position"),r=this.geometry.getAttribute("color");return s.array.set(this.cloud.positions.subarray(0,i*3)),this.colour(this.cloud,r.array,i),s.needsUpdate=!0,r.needsUpdate=!0,this.geometry.setDrawRange(0,i),this.lastCount=i,this.pending=!0,this.pendingStamp=wl(e.header),Ut.busyMs.cloudUnpack+=performance.now()-t,this.dirty=!0,i}colour(e,t,i){let s=this.colourBy==="intensity"&&i>0&&!Number.isNaN(e.intensity[0]),r=1/0,o=-1/0;for(let l=0;l<i;l++){let c=s?e.intensity[l]:e.positions[l*3+2];c<r&&(r=c),c>o&&(o=c)}let a=(Hh-1)/(o>r?o-r:1);for(let l=0;l<i;l++){let c=Math.round(((s?e.intensity[l]:e.positions[l*3+2])-r)*a)*3;t[l*3]=Rd[c],t[l*3+1]=Rd[c+1],t[l*3+2]=Rd[c+2]}}render(){this.dirty=!1;let e=performance.now();this.renderer.render(this.scene,this.camera),Ut.busyMs.cloudRender+=performance.now()-e,this.pending&&this.onShown&&this.onShown(this.pendingStamp),this.pending=!1}destroy(){cancelAnimationFrame(this.raf),this.ro.disconnect(),this.controls.dispose(),this.geometry.dispose(),this.points.material.dispose(),this.renderer.dispose(),this.renderer.domElement.remove()}};function Nr(n,e,t,i){(n instanceof HTMLButtonElement||n instanceof HTMLSelectElement)&&(n.disabled=!0),n.title=t,i.textContent=`Disabled: ${t}`,i.className="why",Ut.disabled[e]=t}function f_(n,e,t,i,s,r){let o=`/${t}/`,a=ge("div","task nav");a.appendChild(ge("h3","","Navigation goal"));let l=ge("p","muted","Looking for the robot's navigation action…"),c=ge("progress");c.max=1,c.value=0;let h=ge("div","navstate",""),f=Gs("Cancel goal","danger");f.disabled=!0,a.append(l,c,h,f);let u=ge("div","task init");u.appendChild(ge("h3","","Initial pose"));let p=Gs("Set initial pose: click the map"),g=ge("p","muted",`publishes geometry_msgs/msg/PoseWithCovarianceStamped on ${o}initialpose`);u.append(p,g);let S=ge("div","task svc");S.appendChild(ge("h3","","Call a service"));let d=ge("select"),m=ge("form","svcform"),y=ge("div","svcout"),A=ge("p","muted","Listing the services you may call…");S.append(d,A,m,y),n.append(a,u,S);let b="goal",C=null,E=null,x=!1,T=!1;i.onClick=async(P,B)=>{if(b==="init"){if(b="goal",p.classList.remove("armed"),!T)return;let z=s()?.yaw??0;e.publish(`${o}initialpose`,{header:{frame_id:"map",stamp:{sec:0,nanosec:0}},pose:{pose:{position:{x:P,y:B,z:0},orientation:{x:0,y:0,z:Math.sin(z/2),w:Math.cos(z/2)}},covariance:new Array(36).fill(0)}},L=>Nr(p,"initialpose",L,g)),g.textContent=`initial pose sent: (${un(P,2)}, ${un(B,2)})`;return}E?k(P,B):x&&(i.goal={x:P,y:B},i.invalidate(),e.publish(`${o}goal_pose`,{header:{frame_id:"map",stamp:{sec:0,nanosec:0}},pose:{position:{x:P,y:B,z:0},orientation:{x:0,y:0,z:0,w:1}}},z=>Nr(a,"goal",z,l)),h.textContent=`goal published on ${o}goal_pose: (${un(P,2)}, ${un(B,2)})`)};function k(P,B){if(!E)return;let z=E;i.goal={x:P,y:B},i.invalidate();let L=s(),H=L?Math.hypot(L.x-P,L.y-B):1;c.value=0,h.textContent=`goal (${un(P,2)}, ${un(B,2)}) sent to ${z.name}…`;let W=e.sendGoal(z.name,z.type,{x:P,y:B},D=>{if(C!==W)return;let te=Number(D?.distance_remaining);Ut.feedback.push(te),Ut.feedback.length>500&&Ut.feedback.splice(0,250),si("feedback"),Number.isFinite(te)&&(c.value=H>0?Math.max(0,Math.min(1,1-te/H)):1,h.textContent=`driving to (${un(P,2)}, ${un(B,2)}): ${un(te,2)} m to go`)});C=W,f.disabled=!1,W.result.then(D=>{if(Ut.lastResult=D,C!==W)return;let te=D.status===4?"reached":D.status===5?"canceled":D.status===6?"aborted":`ended (status ${D.status})`,X=D.values??{};h.textContent=`goal ${te}${X.x!=null?` at (${un(X.x,2)}, ${un(X.y,2)})`:""}`,D.status===4&&(c.value=1),f.disabled=!0,C=null},D=>{C===W&&(C=null,f.disabled=!0,D instanceof zs&&/not allowed/.test(D.message)?Nr(a,"navigate",D.message,l):h.textContent=`goal failed: ${D.message}`)})}f.addEventListener("click",()=>{C?.cancel(),h.textContent+=" · cancel requested"}),p.addEventListener("click",()=>{b=b==="init"?"goal":"init",p.classList.toggle("armed",b==="init")}),r.push(()=>C?.cancel()),(async()=>{let[P,B]=await Promise.all([e.call("/rosapi/action_servers").then(D=>D.action_servers??[],()=>[]),e.call("/rosapi/services").then(D=>D.services??[],()=>[])]),z=P.filter(D=>D.startsWith(o)),L=z.find(D=>/navigate/.test(D))??z[0];if(L){let D=await e.call("/rosapi/service_type",{service:L}).then(te=>String(te.type??""),()=>"");E={name:L,type:D},l.textContent=`Click on the map to send a goal to ${L} (${D}).`}else{let D=await e.advertise(`${o}goal_pose`,"geometry_msgs/msg/PoseStamped");D?Nr(f,"navigate",`the hub lists no navigation action you may use on ${t}, and refused the goal topic: ${D}`,l):(x=!0,r.push(()=>e.unadvertise(`${o}goal_pose`)),l.textContent=`No navigation action listed for you; clicks publish a PoseStamped on ${o}goal_pose.`)}let H=await e.advertise(`${o}initialpose`,"geometry_msgs/msg/PoseWithCovarianceStamped");H?Nr(p,"initialpose",H,g):(T=!0,r.push(()=>e.unadvertise(`${o}initialpose`)));let W=B.filter(D=>D.startsWith(o));if(W.length===0){Nr(d,"services",`the hub lists no services of ${t} you may call (/rosapi/services)`,A);return}for(let D of W)d.appendChild(new Option(D,D));A.textContent="",d.addEventListener("change",()=>U(d.value)),U(W[0])})();async function U(P){m.replaceChildren(ge("p","muted","loading the request type…")),y.replaceChildren();let B="",z=[];try{B=String((await e.call("/rosapi/service_type",{service:P})).type),z=(await e.call("/rosapi/service_request_details",{type:B})).typedefs??[]}catch(te){m.replaceChildren(ge("p","why",`cannot read the type of ${P}: ${te.message}`));return}let L=Bp(z);m.replaceChildren(ge("div","muted",`${B} request`));let H=[],W=(te,X,q)=>{X&&X.fieldnames.forEach((j,ae)=>{let ce=X.fieldtypes[ae],ee=z.find(Me=>Me.type===ce);if(ee&&X.fieldarraylen[ae]===-1)return W(te[j],ee,[...q,j]);let pe=ge("label","",`${[...q,j].join(".")} (${ce}${X.fieldarraylen[ae]>=0?"[]":""})`),fe=ge("input");fe.name=[...q,j].join("."),ce==="bool"&&X.fieldarraylen[ae]===-1?fe.type="checkbox":fe.value=JSON.stringify(te[j]),pe.appendChild(fe),m.appendChild(pe),H.push({path:[...q,j],input:fe,kind:ce==="bool"&&X.fieldarraylen[ae]===-1?"bool":ce==="string"&&X.fieldarraylen[ae]===-1?"string":"json"})})};W(L,z[0],[]),H.length===0&&m.appendChild(ge("p","muted","(no request fields)"));for(let te of H)te.kind==="string"&&(te.input.value="");let D=Gs("Call","primary");D.type="submit",m.appendChild(D),m.onsubmit=async te=>{te.preventDefault();let X=structuredClone(L);try{for(let q of H){let j=X;for(let ce of q.path.slice(0,-1))j=j[ce];let ae=q.path[q.path.length-1];j[ae]=q.kind==="bool"?q.input.checked:q.kind==="string"?q.input.value:JSON.parse(q.input.value||"null")}}catch(q){y.replaceChildren(ge("p","why",`bad value: ${q.message}`));return}D.disabled=!0,y.replaceChildren(ge("p","muted",`calling ${P}…`));try{let q=await e.call(P,X,10);Ut.lastServiceResponse={service:P,ok:!0,values:q},si("service-response"),y.replaceChildren(ge("div","ok","response:"),ra(q))}catch(q){Ut.lastServiceResponse={service:P,ok:!1,error:q.message},y.replaceChildren(ge("p","why",`refused or failed: ${q.message}`)),q instanceof zs&&/not allowed/.test(q.message)&&Nr(D,`call:${P}`,q.message,A)}finally{Ut.disabled[`call:${P}`]||(D.disabled=!1)}}}}function ar(n,e,t=""){let i=ge("section",`panel ${t}`),s=ge("h2","",e),r=ge("span","info");s.appendChild(r);let o=ge("div","body");return i.append(s,o),n.appendChild(i),{box:i,body:o,info:r}}var Cd=class{n=0;lastLatency=NaN;note(e){this.n++;let t=wl(e?.header);t!=null&&(this.lastLatency=Date.now()-t)}};function d_(n,e,t){n.innerHTML="";let i=[],s=new Map,r=B=>{let z=s.get(B);return z||s.set(B,z=new Cd),z},o=ge("div","robot-title");o.append(ge("a","back","← fleet"),ge("h1","",t),ge("span","badge","…")),o.firstChild.href="#/",n.appendChild(o);let a=o.lastChild,l=ge("div","robot-grid");n.appendChild(l);let c=ar(l,"Map (odometry path, scan, goal)","wide"),h=new Zr(c.body);h.selected=t,h.canvas.id="robot-map",Ut.mapToScreen=(B,z)=>h.toScreen(B,z),i.push(()=>h.destroy(),()=>Ut.mapToScreen=null);let f=ar(l,"Tasking","tasking"),u=ar(l,"Laser scan"),p=ar(l,"Point cloud (3D)"),g=ar(l,"Camera"),S=ar(l,"Topics","full"),d=ar(l,"Inspector","inspector"),m=ar(l,"Link quality (last 5 minutes)","wide"),y=null,A=!1;function b(B){A=!0;let z=B.filter(Ce=>Ce.name.startsWith(`/${t}/`)),L=Ce=>z.filter(Ne=>Ne.type===Ce),H="#2f80ed",W=Mu(t,B),D=L("nav_msgs/msg/Odometry")[0];for(let Ce of[W,D&&{topic:D.name,type:D.type}])Ce&&i.push(e.subscribe(Ce.topic,Ne=>{if(r(Ce.topic).note(Ne),Ce.topic===D?.name&&si("odom"),Ce.topic!==W?.topic)return;let Be=El(Ne);Be&&(y=Be,h.setPose(t,Be,H),Ut.poses[t]={...Be,at:Date.now()},si("pose"))},{type:Ce.type,throttle_rate:50,queue_length:1,compression:"none"}));W?c.info.textContent=W.topic:c.info.textContent="no pose or odometry topic";let te=L("sensor_msgs/msg/LaserScan")[0];if(te){let Ce=ge("canvas","scan");u.body.appendChild(Ce);let Ne=null,Be=10,xt=!1;i.push(e.subscribe(te.name,at=>{if(r(te.name).note(at),Ne=Up(at),Be=at.range_max||Be,xt=!0,si("scan"),y){let Ct=Math.cos(y.yaw),Ze=Math.sin(y.yaw),ft=new Float32Array(Ne.length);for(let pt=0;pt<Ne.length;pt+=2)ft[pt]=y.x+Ct*Ne[pt]-Ze*Ne[pt+1],ft[pt+1]=y.y+Ze*Ne[pt]+Ct*Ne[pt+1];h.scan=ft,h.invalidate()}},{type:te.type,queue_length:1}));let Rt=0,Bt=()=>{if(Rt=requestAnimationFrame(Bt),!xt||!Ne)return;xt=!1;let at=devicePixelRatio||1,Ct=Ce.clientWidth,Ze=Ce.clientHeight;Ce.width=Ct*at,Ce.height=Ze*at;let ft=Ce.getContext("2d");ft.setTransform(at,0,0,at,0,0),ft.fillStyle="#0b1016",ft.fillRect(0,0,Ct,Ze);let pt=Math.min(Ct,Ze)/2/Math.min(Be,15);ft.strokeStyle="#1f2a35";for(let bt=2;bt<=14;bt+=2)ft.beginPath(),ft.arc(Ct/2,Ze/2,bt*pt,0,7),ft.stroke();ft.fillStyle="#f2c94c";for(let bt=0;bt<Ne.length;bt+=2)ft.fillRect(Ct/2-Ne[bt+1]*pt-1,Ze/2-Ne[bt]*pt-1,2,2);ft.fillStyle="#2f80ed",ft.beginPath(),ft.moveTo(Ct/2,Ze/2-10),ft.lineTo(Ct/2-6,Ze/2+6),ft.lineTo(Ct/2+6,Ze/2+6),ft.fill(),u.info.textContent=`${te.name} · ${Ne.length/2} points · 2 m rings`};Rt=requestAnimationFrame(Bt),i.push(()=>cancelAnimationFrame(Rt))}else u.body.appendChild(ge("p","muted","This robot publishes no LaserScan."));let X=L("sensor_msgs/msg/PointCloud2")[0];if(X){let Ce=new Vh(p.body),Ne=ge("select");for(let Be of["height","intensity"])Ne.appendChild(new Option(`colour by ${Be}`,Be));Ne.addEventListener("change",()=>Ce.colourBy=Ne.value),p.box.querySelector("h2").appendChild(Ne),Ce.onShown=Be=>{Be!=null&&Ut.cloudAgesMs.push(Date.now()-Be),Ut.cloudAgesMs.length>2e3&&Ut.cloudAgesMs.splice(0,1e3),si("cloud-rendered")},i.push(e.subscribe(X.name,Be=>{r(X.name).note(Be);let xt=Ce.show(Be);si("cloud"),p.info.textContent=`${X.name} · ${xt.toLocaleString()} points`},{type:X.type,queue_length:1})),i.push(()=>Ce.destroy())}else p.body.appendChild(ge("p","muted","This robot publishes no PointCloud2."));let q=L("sensor_msgs/msg/CompressedImage")[0];if(q){let Ce=ge("img","camera"),Ne=ge("canvas","camera bytes"),Be=ge("p","muted");g.body.append(Ce,Ne,Be);let xt="",Rt=!1;i.push(e.subscribe(q.name,async Bt=>{if(r(q.name).note(Bt),si("camera"),Rt)return;Rt=!0;let at=bu(Bt.data),Ct=Fp(at);try{let Ze=new Blob([at],{type:`image/${Ct==="png"?"png":"jpeg"}`});(await createImageBitmap(Ze)).close(),xt&&URL.revokeObjectURL(xt),xt=URL.createObjectURL(Ze),Ce.src=xt,Ce.style.display="",Ne.style.display="none",Be.textContent="",g.info.textContent=`${q.name} · ${Bt.format} · ${(at.length/1024).toFixed(0)} KiB`}catch{Ce.style.display="none",Ne.style.display="";let Ze=Math.max(1,Math.floor(Math.sqrt(at.length)));Ne.width=Ze,Ne.height=Ze;let ft=Ne.getContext("2d"),pt=ft.createImageData(Ze,Ze);for(let bt=0;bt<Ze*Ze;bt++){let O=at[bt];pt.data[bt*4]=pt.data[bt*4+1]=pt.data[bt*4+2]=O,pt.data[bt*4+3]=255}ft.putImageData(pt,0,0),Be.textContent=`not a decodable ${Bt.format} image (${Ct==="unknown"?"no image header":`${Ct} header, undecodable body`}): showing its ${at.length.toLocaleString()} bytes as grey levels`,g.info.textContent=`${q.name} · ${Bt.format} · ${(at.length/1024).toFixed(0)} KiB`}finally{Rt=!1}},{type:q.type,queue_length:1})),i.push(()=>xt&&URL.revokeObjectURL(xt))}else g.body.appendChild(ge("p","muted","This robot publishes no CompressedImage."));let j=ge("select"),ae=ge("div","tree");d.body.append(j,ae);let ce=new Set([te?.name,X?.name,q?.name,W?.topic]),ee=z.find(Ce=>!ce.has(Ce.name)&&Ce.rate_hz>0)??z.find(Ce=>!ce.has(Ce.name))??z[0];for(let Ce of z)j.appendChild(new Option(`${Ce.name} (${Ce.type})`,Ce.name));ee&&(j.value=ee.name);let pe=null,fe=null,Me=0,ye=0,qe=performance.now(),it=()=>{pe?.();let Ce=z.find(Ne=>Ne.name===j.value);Ce&&(ye=0,qe=performance.now(),fe=null,ae.textContent="waiting for a message…",pe=e.subscribe(Ce.name,(Ne,Be,xt)=>{r(Ce.name).note(Ne),fe=Ne,Me=xt,ye++,si("inspector")},{type:Ce.type,queue_length:1,throttle_rate:200}))};j.addEventListener("change",it),it();let We=window.setInterval(()=>{if(!fe)return;let Ce=ye/((performance.now()-qe)/1e3),Ne=r(j.value).lastLatency;d.info.textContent=`${un(Ce)} msg/s shown · latency ${un(Ne,0)} ms · ${Math.round(performance.now()-Me)} ms ago`,ae.replaceChildren(ra(Ml(fe),j.value))},1e3);i.push(()=>{clearInterval(We),pe?.()}),f_(f.body,e,t,h,()=>y,i)}let C=ge("table","topics");C.innerHTML="<thead><tr><th>topic</th><th>type</th><th>rate (hub)</th><th>bandwidth (hub)</th><th>latency (here)</th><th>drops</th></tr></thead>";let E=ge("tbody");C.appendChild(E),S.body.appendChild(C);let x=new Map,T=new Sr(3,300),k=new Gl(m.body,T,[{label:"RTT ms",colour:"#f2994a",scale:"ms"},{label:"latency ms",colour:"#eb5757",scale:"ms"},{label:"link MB/s",colour:"#27ae60",scale:"r"}],Math.max(400,m.body.clientWidth||900),180);i.push(()=>k.destroy());async function U(){let B,z;try{[{robots:B},{topics:z}]=await Promise.all([yi("/api/v1/robots"),yi("/api/v1/topics")])}catch(W){a.textContent=`cannot read the hub: ${W.message}`;return}let L=B.find(W=>W.name===t);a.textContent=L?L.online?"online":"offline":"not visible to you",a.className=`badge ${L?.online?"ok":"off"}`,n.classList.toggle("offline",!!L&&!L.online),!A&&L?.online&&b(z);let H=Date.now()/1e3;L?.online&&T.push(H,L.rtt_ms??null,L.latency_ms??null,L.link_rate_bps!=null?L.link_rate_bps/1e6:null),k.update();for(let W of z.filter(D=>D.name.startsWith(`/${t}/`))){let D=x.get(W.name);if(!D){let q=ge("tr"),j=Array.from({length:6},()=>ge("td"));j[0].textContent=W.name,j[1].textContent=W.type,q.append(...j),E.appendChild(q);let ae=[new Sr(1,120),new Sr(1,120),new Sr(1,120)];D={rate:new oo(j[2],ae[0],"#2f80ed"),bw:new oo(j[3],ae[1],"#27ae60"),lat:new oo(j[4],ae[2],"#eb5757"),s:ae,drops:j[5]},x.set(W.name,D)}let te=s.get(W.name)?.lastLatency??NaN;D.s[0].push(H,W.rate_hz),D.s[1].push(H,W.bandwidth_bps),D.s[2].push(H,Number.isFinite(te)?te:null),D.rate.update(`${un(W.rate_hz)} Hz`),D.bw.update($r(W.bandwidth_bps)),D.lat.update(Number.isFinite(te)?`${un(te,0)} ms`:"not subscribed");let X=Object.entries(W.drops??{}).filter(([,q])=>q);D.drops.textContent=X.length?X.map(([q,j])=>`${q} ${j}`).join(", "):"0"}}U();let P=window.setInterval(U,1e3);return i.push(()=>clearInterval(P),()=>x.forEach(B=>{B.rate.destroy(),B.bw.destroy(),B.lat.destroy()})),()=>i.forEach(B=>B())}var ki=n=>document.getElementById(n),Wh=ki("main"),p_=ki("conn"),jE=ki("who"),m_=ki("signin"),g_=ki("signout"),Id=ki("estop"),Pd=ki("estop-note"),Ld=ki("login");function __(){try{let n=JSON.parse(localStorage.getItem("fleetlink.estop")??"null");if(n?.topic&&n?.type)return n}catch{}return{topic:"/fleet/estop",type:"std_msgs/msg/Bool"}}var lr,Xh=()=>{};function Nd(){lr?.close(),lr=new Sl(cs.wsUrl()),globalThis.fleetlinkRosbridge=lr,lr.onState=(e,t)=>{p_.textContent=e==="open"?"connected":e==="connecting"?"connecting…":`disconnected (${t}), retrying`,p_.className=`conn ${e}`,e==="open"&&QE()};let n=cs.principal();jE.textContent=n==="token"?"signed in with a token":n?`signed in as ${n}`:"anonymous (read-only where the hub allows)",m_.hidden=!!n,g_.hidden=!n}async function QE(){let n=__(),e=await lr.advertise(n.topic,n.type);Id.disabled=!!e,Id.title=e?`Disabled: ${e}`:`publishes ${n.type} {data: true} on ${n.topic}`,Pd.textContent=e?`e-stop disabled: ${e}`:`→ ${n.topic}`,e?Ut.disabled.estop=e:delete Ut.disabled.estop}Id.addEventListener("click",()=>{let n=__(),e=n.type.endsWith("/Bool")?{data:!0}:{};for(let t=0;t<3;t++)setTimeout(()=>lr.publish(n.topic,e,i=>Pd.textContent=`e-stop refused: ${i}`),t*100);Pd.textContent=`e-stop sent on ${n.topic} at ${new Date().toLocaleTimeString()}`});function qh(){Xh();let n=location.hash.replace(/^#\/?/,"");document.querySelectorAll("nav a").forEach(e=>e.classList.toggle("active",e.hash===`#/${n.split("/")[0]}`)),Wh.classList.remove("offline"),n.startsWith("robot/")?Xh=d_(Wh,lr,decodeURIComponent(n.slice(6))):n==="admin"?Xh=Np(Wh):Xh=Gp(Wh,lr,e=>location.hash=`#/robot/${encodeURIComponent(e)}`)}m_.addEventListener("click",()=>Ld.showModal());ki("login-cancel").addEventListener("click",()=>Ld.close());ki("login-form").addEventListener("submit",async n=>{n.preventDefault();let e=n.target,t=e.elements.namedItem("user").value,i=e.elements.namedItem("password").value,s=e.elements.namedItem("token").value.trim(),r=ki("login-error");r.textContent="";try{if(s){let o=await fetch("/api/v1/robots",{headers:{Authorization:`Bearer ${s}`}});if(!o.ok)throw new Yo(o.status,(await o.json().catch(()=>null))?.error??`HTTP ${o.status}`);cs.set(s,"token")}else{let o=await yi("/api/v1/login",{method:"POST",body:JSON.stringify({user:t,password:i})});cs.set(o.token,o.principal)}e.reset(),Ld.close(),Nd(),qh()}catch(o){r.textContent=`sign-in refused: ${o.message}`}});g_.addEventListener("click",async()=>{cs.principal()!=="token"&&await yi("/api/v1/logout",{method:"POST"}).catch(()=>{}),cs.clear(),Nd(),qh()});window.addEventListener("hashchange",qh);Nd();qh();var x_=()=>{Ut.renders++,requestAnimationFrame(x_)};requestAnimationFrame(x_);
